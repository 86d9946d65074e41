#!/usr/bin/env python3
"""fix hele_shaw/field writes valid VTK: runs in.field_output with hsrod in a
scratch directory, reads the files back with VTK's own XML readers (Debian's
python3-vtk9) and checks them against compute hele_shaw/probe at the same
points: the 2-D image holds the probe's gap-averaged velocity and pressure,
the 3-D image the parabolic gap profile 6 (z/H)(1 - z/H) times it; the walls
file holds the side walls and the pore cylinders at their radius; the
collection lists every frame.

usage: check_field_vtk.py HSROD_EXECUTABLE
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

from vtk_readback import check, failures, read_image

HERE = os.path.dirname(os.path.abspath(__file__))
H = 20e-6                       # gap height [m]
PORE_R, PORE_X = 85e-6, 300e-6  # pore cylinders [m], centred on the side walls y = 0 and y = 200 um


def close(a, b, rel=1e-12, abs_tol=0.0):
    return abs(a - b) <= rel * max(abs(a), abs(b)) + abs_tol


def value_at(image, name, x, y, z):
    pid = image.FindPoint(x, y, z)
    point = image.GetPoint(pid)
    assert math.dist(point, (x, y, z)) < 1e-12, (point, (x, y, z))
    return vtk_to_numpy(image.GetPointData().GetArray(name))[pid]


def main():
    hsrod = os.path.abspath(sys.argv[1])
    work = tempfile.mkdtemp(prefix="hsrod-field-")
    try:
        shutil.copy(os.path.join(HERE, "in.field_output"), work)
        run = subprocess.run([hsrod, "-in", "in.field_output", "-log", "none"], cwd=work,
                             capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            print(run.stdout[-3000:], run.stderr[-3000:])
            raise SystemExit("hsrod failed")
        probe_lines = [l.split() for l in open(os.path.join(work, "probe_values.txt"))
                       if l.strip() and not l.startswith("#")]
        values = [float(v) for v in probe_lines[-1]]
        points = [(300e-6, 100e-6), (300e-6, 110e-6), (150e-6, 60e-6), (305e-6, 115e-6), (300e-6, 5e-6)]
        probes = [dict(ux=values[4 * k], uy=values[4 * k + 1], p=values[4 * k + 2], fluid=values[4 * k + 3])
                  for k in range(len(points))]
        check([p["fluid"] for p in probes] == [1, 1, 1, 1, 0], "probe fluid flags: four fluid points, one in a cylinder")

        # Frames: the 2-D field every 5 steps of 10, the 3-D every 10, each listed in its collection.
        for prefix, steps in (("flow2d", [0, 5, 10]), ("flow3d", [0, 10])):
            for s in steps:
                check(os.path.exists(os.path.join(work, "%s_%d.vti" % (prefix, s))), "%s_%d.vti written" % (prefix, s))
            listed = [d.get("file") for d in ET.parse(os.path.join(work, prefix + ".pvd")).getroot().iter("DataSet")]
            check(listed == ["%s_%d.vti" % (prefix, s) for s in steps], prefix + ".pvd lists its frames " + str(listed))

        # 2-D image: lattice over the planform at mid-gap, 5 um spacing.
        img = read_image(os.path.join(work, "flow2d_10.vti"))
        check(img.GetDimensions() == (121, 41, 1), "2-D image dimensions %s (600 x 200 um at 5 um)" % (img.GetDimensions(),))
        check(all(close(a, b) for a, b in zip(img.GetSpacing()[:2], (5e-6, 5e-6))), "2-D image spacing 5 um")
        check(close(img.GetOrigin()[2], H / 2), "2-D image at mid-gap")
        for (x, y), pr in zip(points, probes):
            u = value_at(img, "velocity", x, y, H / 2)
            p = value_at(img, "pressure", x, y, H / 2)
            f = value_at(img, "fluid", x, y, H / 2)
            # The probe's numbers pass through fix print's %.15g; the file's are 17 digits.
            ok = close(u[0], pr["ux"], 1e-13, 1e-15) and close(u[1], pr["uy"], 1e-13, 1e-15) \
                and close(p, pr["p"], 1e-13, 1e-12) and f == pr["fluid"] and u[2] == 0.0
            check(ok, "2-D field = probe at (%g, %g) um: u = (%.6g, %.6g) m/s, p = %.6g Pa"
                  % (x * 1e6, y * 1e6, u[0], u[1], p))
        speed = vtk_to_numpy(img.GetPointData().GetArray("speed"))
        fluid = vtk_to_numpy(img.GetPointData().GetArray("fluid"))
        check(speed[fluid == 0].max() == 0.0, "no velocity in walls")
        check(close(speed.max(), probes[0]["ux"], 0.05), "fastest point is in the pore throat (%.4g vs %.4g m/s)"
              % (speed.max(), probes[0]["ux"]))

        # 3-D image: 5 layers through the gap, parabolic profile, same pressure.
        img3 = read_image(os.path.join(work, "flow3d_10.vti"))
        check(img3.GetDimensions() == (121, 41, 5), "3-D image dimensions %s" % (img3.GetDimensions(),))
        before = len(failures)
        for (x, y), pr in zip(points, probes):
            for k in range(5):
                z = k * H / 4
                factor = 6 * (z / H) * (1 - z / H)
                u = value_at(img3, "velocity", x, y, z)
                p = value_at(img3, "pressure", x, y, z)
                if not (close(u[0], factor * pr["ux"], 1e-13, 1e-15) and close(u[1], factor * pr["uy"], 1e-13, 1e-15)
                        and close(p, pr["p"], 1e-13, 1e-12)):
                    check(False, "3-D field at (%g, %g, %g) um = %.4f x probe" % (x * 1e6, y * 1e6, z * 1e6, factor))
        check(len(failures) == before, "3-D field = 6 (z/H)(1 - z/H) x probe velocity, probe pressure, at 5 points x 5 layers")
        check(close(value_at(img3, "velocity", 300e-6, 100e-6, H / 2)[0], 1.5 * probes[0]["ux"], 1e-13),
              "3-D mid-gap velocity = 3/2 x gap average at the throat")

        # Walls: two side walls, the pore cylinders' halves in the channel at radius R, two gap outlines.
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(work, "flow2d_walls.vtp"))
        reader.Update()
        walls = reader.GetOutput()
        tag = vtk_to_numpy(walls.GetCellData().GetArray("wall"))
        check(walls.GetNumberOfPolys() == 2 + 64 and walls.GetNumberOfLines() == 2,
              "walls: %d quads (2 side walls + 2 x 32 cylinder facets), %d outlines"
              % (walls.GetNumberOfPolys(), walls.GetNumberOfLines()))
        check(sorted(set(tag.tolist())) == [-1, 0, 1, 2], "wall tags: outlines, side walls, two cylinders")
        pts = vtk_to_numpy(walls.GetPoints().GetData())
        radii = []
        for cid in range(walls.GetNumberOfCells()):
            if tag[cid] < 1:
                continue
            cell = walls.GetCell(cid)
            cy = 0.0 if tag[cid] == 1 else 200e-6
            for n in range(cell.GetNumberOfPoints()):
                q = pts[cell.GetPointId(n)]
                radii.append(math.hypot(q[0] - PORE_X, q[1] - cy))
        check(max(abs(r - PORE_R) for r in radii) < 1e-15, "cylinder facets on radius 85 um")
        check(pts[:, 2].min() == 0.0 and close(pts[:, 2].max(), H), "walls span the gap 0..20 um")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        raise SystemExit("%d check(s) failed" % len(failures))
    print("all VTK checks passed")


if __name__ == "__main__":
    main()
