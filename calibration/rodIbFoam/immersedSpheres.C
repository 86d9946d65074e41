/*---------------------------------------------------------------------------*\
 hsrod calibration: direct-forcing immersed boundary for rigid spheres.
 See immersedSpheres.H for the method and references. This file: reading the
 set-up, the bad-input checks and the report; the steps are in
 immersedSpheresMarking.C, immersedSpheresForcing.C, immersedSpheresFarField.C.
\*---------------------------------------------------------------------------*/
#include "immersedSpheres.H"
#include "vec3Conversion.H"

#include <stdexcept>

using namespace Foam;

namespace hsrodFoam
{

namespace
{
    fileName caseFile(const fvMesh& mesh, const fileName& f)
    {
        if (f.isAbsolute()) return f;
        return mesh.time().rootPath()/mesh.time().globalCaseName()/"constant"/f;
    }

    volScalarField makeScalar(const fvMesh& mesh, const word& name, const dimensionSet& dims,
                              IOobject::writeOption w)
    {
        return volScalarField
        (
            IOobject(name, mesh.time().timeName(), mesh, IOobject::NO_READ, w),
            mesh, dimensionedScalar(dims, Zero)
        );
    }
}


fileName outputDir(const Time& runTime)
{
    const fileName dir = runTime.rootPath()/runTime.globalCaseName()/"postProcessing"/"rodIbFoam";
    mkDir(dir);
    return dir;
}


immersedSpheres::immersedSpheres
(
    const fvMesh& mesh,
    const volVectorField& /*U*/,
    const dimensionedScalar& nu
)
:
    mesh_(mesh),
    nu_(nu.value()),
    dict_
    (
        IOobject
        (
            "immersedBoundaryProperties", mesh.time().constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    ),
    forcing_(dict_.lookupOrDefault<word>("forcing", "linearWall")),
    alphaModel_(dict_.lookupOrDefault<word>("alphaModel", "volumeFraction")),
    nSub_(dict_.lookupOrDefault<label>("nSubSample", 5)),
    smoothWidth_(dict_.lookupOrDefault<scalar>("smoothWidth", 1.0)),
    alphaMax_(dict_.lookupOrDefault<scalar>("alphaMax", 0.999)),
    minCellsPerDiameter_(dict_.lookupOrDefault<scalar>("minCellsPerDiameter", 6.0)),
    alpha_(makeScalar(mesh, "alphaSolid", dimless, IOobject::AUTO_WRITE)),
    alphaSum_(makeScalar(mesh, "alphaSolidSum", dimless, IOobject::NO_WRITE)),
    weightSum_(makeScalar(mesh, "ibWeightSum", dimless, IOobject::NO_WRITE)),
    geomSum_(makeScalar(mesh, "ibGeomCoeff", dimless/dimArea, IOobject::NO_WRITE)),
    lambda_(makeScalar(mesh, "lambdaIB", dimless/dimTime, IOobject::NO_WRITE)),
    Us_
    (
        IOobject("Usolid", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh, dimensionedVector(dimVelocity, Zero)
    ),
    cellBb_(mesh.nCells()),
    cellH_(cbrt(mesh.V().field()))
{
    if (alphaModel_ != "volumeFraction" && alphaModel_ != "smoothed")
    {
        FatalIOErrorInFunction(dict_)
            << "alphaModel " << alphaModel_ << " unknown; use volumeFraction or smoothed"
            << exit(FatalIOError);
    }
    if (forcing_ != "linearWall" && forcing_ != "volumeFraction")
    {
        FatalIOErrorInFunction(dict_)
            << "forcing " << forcing_ << " unknown; use linearWall or volumeFraction"
            << exit(FatalIOError);
    }
    if (nSub_ < 1 || smoothWidth_ <= 0 || alphaMax_ <= 0 || alphaMax_ >= 1)
    {
        FatalIOErrorInFunction(dict_)
            << "need nSubSample >= 1, smoothWidth > 0, 0 < alphaMax < 1" << exit(FatalIOError);
    }

    try
    {
        const auto mode =
            hsrod::calib::parse_motion_mode(dict_.lookupOrDefault<word>("motion", "fixed"));
        // coupled mode: the DEM side supplies the spheres; a file is optional
        if (mode != hsrod::calib::MotionMode::Coupled || dict_.found("spheres"))
        {
            spheres_ = hsrod::calib::SphereSet::read_csv
            (
                caseFile(mesh, dict_.get<fileName>("spheres"))
            );
        }
        spheres_.set_motion
        (
            hsrod::calib::parse_motion_mode(dict_.lookupOrDefault<word>("motion", "fixed"))
        );
        if (spheres_.motion() == hsrod::calib::MotionMode::Table)
        {
            spheres_.read_path_table(caseFile(mesh, dict_.get<fileName>("pathTable")));
        }
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << "immersed spheres: " << e.what() << exit(FatalError);
    }

    const labelListList& cp = mesh.cellPoints();
    forAll(cellBb_, celli)
    {
        cellBb_[celli] = boundBox(mesh.points(), cp[celli], false);
    }
    marks_.resize(spheres_.size());
}


scalar immersedSpheres::minDiameter() const
{
    scalar dMin = GREAT;
    for (const auto& s : spheres_.spheres()) dMin = min(dMin, s.d);
    return dMin;
}


scalar immersedSpheres::cellSizeAtSpheres() const
{
    scalar h = 0;
    for (const auto& s : spheres_.spheres())
    {
        const label c = mesh_.findCell(point(s.x[0], s.x[1], s.x[2]));
        if (c >= 0) h = max(h, cellH_[c]);
    }
    reduce(h, maxOp<scalar>());
    return h;
}


void immersedSpheres::checkAndReport(const hsrod::calib::RunParameters& base)
{
    // 1. every sphere centre inside the mesh, the sphere inside its bounds
    const boundBox bb(mesh_.points(), true);
    for (const auto& s : spheres_.spheres())
    {
        const point X(s.x[0], s.x[1], s.x[2]);
        label found = mesh_.findCell(X) >= 0 ? 1 : 0;
        reduce(found, sumOp<label>());
        if (!found)
        {
            FatalErrorInFunction
                << "sphere id " << s.id << " at " << X << " (d = " << s.d
                << " m) lies outside the mesh, whose bounds are " << bb << nl
                << "    fix constant/immersedBoundaryProperties or the spheres file"
                << exit(FatalError);
        }
        const vector r(s.radius(), s.radius(), s.radius());
        if (!bb.contains(X - r) || !bb.contains(X + r))
        {
            FatalErrorInFunction
                << "sphere id " << s.id << " at " << X << " (d = " << s.d
                << " m) crosses the mesh boundary " << bb << exit(FatalError);
        }
    }

    // 2. resolution, stability and cost report; hard violations stop here
    hsrod::calib::RunParameters p = base;
    p.d_min = minDiameter();
    p.v_particle = 0;
    for (const auto& s : spheres_.spheres())
    {
        p.v_particle = max(p.v_particle, mag(toVec(s.v)));
    }
    p.h_sphere = cellSizeAtSpheres();
    p.min_cells_per_diameter = minCellsPerDiameter_;
    p.coupled = spheres_.motion() == hsrod::calib::MotionMode::Coupled;
    if (p.rho_p <= 0)   // coupled runs pass the DEM particles' density
    {
        p.rho_p = dict_.lookupOrDefault<scalar>("rhoParticle", 0);
    }
    if (p.dt_dem <= 0)
    {
        p.dt_dem = dict_.lookupOrDefault<scalar>("demTimeStep", 0);
        p.coupling_interval = dict_.lookupOrDefault<label>("couplingInterval", 0);
    }
    p.cost_per_cell_iter = dict_.lookupOrDefault<scalar>("costPerCellIteration", 1.0e-6);
    p.n_cells = returnReduce(mesh_.nCells(), sumOp<label>());

    const hsrod::calib::Report rep = hsrod::calib::make_report(p);
    Info<< nl << rep.text.c_str() << nl;
    if (!rep.errors.empty() && dict_.lookupOrDefault<bool>("allowUnstableCoupling", false))
    {
        bool onlyCoupling = true;
        for (const auto& e : rep.errors)
        {
            onlyCoupling = onlyCoupling && e.find("coupling unstable") != std::string::npos;
        }
        if (onlyCoupling)
        {
            WarningInFunction << "allowUnstableCoupling: continuing despite an exchange gain >= 1" << nl;
            return;
        }
    }
    if (!rep.errors.empty())
    {
        FatalErrorInFunction << "bad input, nothing computed:" << nl;
        for (const auto& e : rep.errors) FatalError << "    " << e.c_str() << nl;
        FatalError << exit(FatalError);
    }
}

} // namespace hsrodFoam
