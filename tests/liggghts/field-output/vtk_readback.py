"""Shared helpers of the VTK read-back tests (check_field_vtk.py,
check_field_twoway.py): a pass/fail log and ParaView's own reader."""
import vtk

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def read_image(path):
    """A .vti file through VTK's XML reader, as ParaView reads it."""
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image is None or image.GetNumberOfPoints() == 0:
        raise RuntimeError("VTK could not read " + path)
    return image
