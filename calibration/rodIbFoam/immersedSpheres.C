/*---------------------------------------------------------------------------*\
 hsrod calibration: direct-forcing immersed boundary for rigid spheres.
 See immersedSpheres.H for the method and references.
\*---------------------------------------------------------------------------*/
#include "immersedSpheres.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <stdexcept>

using namespace Foam;

namespace hsrodFoam
{

namespace
{
    vector toVec(const hsrod::calib::Vec3& v) { return vector(v[0], v[1], v[2]); }
    hsrod::calib::Vec3 toArr(const vector& v) { return {v.x(), v.y(), v.z()}; }

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
    p.d_min = GREAT;
    p.v_particle = 0;
    for (const auto& s : spheres_.spheres())
    {
        p.d_min = min(p.d_min, s.d);
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


void immersedSpheres::markSphere(std::size_t k)
{
    const auto& s = spheres_.spheres()[k];
    const point X(s.x[0], s.x[1], s.x[2]);
    const scalar r = s.radius();
    auto& marks = marks_[k];
    marks.clear();

    const bool smooth = (alphaModel_ == "smoothed");
    const vectorField& C = mesh_.C().primitiveField();

    forAll(cellBb_, celli)
    {
        const boundBox& b = cellBb_[celli];
        const scalar band = smooth ? 0.5*smoothWidth_*cellH_[celli] : 0;
        // quick reject: sphere grown by the smoothing band / one cell misses the cell box
        const point nearest = b.nearest(X);
        const vector span = b.max() - b.min();
        const scalar reach = max(band, cmptMax(span));
        if (magSqr(nearest - X) >= sqr(r + reach)) continue;

        // linear-wall coefficient g [1/m^2] (see header): centre inside -> GREAT;
        // centre at distance s0 outside -> sum_i max(0, |n_i| h_i - s0)/(h_i^2 s0)
        scalar g = 0;
        {
            const vector rc = C[celli] - X;
            const scalar dist = mag(rc);
            const scalar s0 = dist - r;
            if (s0 <= 0)
            {
                g = GREAT;
            }
            else
            {
                const vector n = rc/dist;
                for (direction i = 0; i < 3; ++i)
                {
                    const scalar hi = span[i];
                    const scalar gap = mag(n[i])*hi - s0;
                    if (gap > 0) g += gap/(hi*hi*s0);
                }
            }
        }

        scalar a = 0;
        if (smooth)
        {
            // cosine ramp of the signed distance s over a width w = smoothWidth h
            const scalar sd = mag(C[celli] - X) - r;
            const scalar w = 2*band;
            if (sd <= -band) a = 1;
            else if (sd >= band) a = 0;
            else a = 0.5*(1 - std::sin(constant::mathematical::pi*sd/w));
        }
        else
        {
            // farthest box corner inside the sphere: the cell is solid
            const point& lo = b.min();
            const point& hi = b.max();
            vector far;
            for (direction i = 0; i < 3; ++i)
            {
                far[i] = max(mag(lo[i] - X[i]), mag(hi[i] - X[i]));
            }
            if (magSqr(far) <= r*r)
            {
                a = 1;
            }
            else
            {
                // n^3 midpoint samples of the cell box (exact for the
                // axis-aligned hexahedra of blockMesh/refineMesh meshes)
                label in = 0;
                const vector box = hi - lo;
                for (label i = 0; i < nSub_; ++i)
                for (label j = 0; j < nSub_; ++j)
                for (label l = 0; l < nSub_; ++l)
                {
                    const point q
                    (
                        lo.x() + (i + 0.5)*box.x()/nSub_,
                        lo.y() + (j + 0.5)*box.y()/nSub_,
                        lo.z() + (l + 0.5)*box.z()/nSub_
                    );
                    if (magSqr(q - X) < r*r) ++in;
                }
                a = scalar(in)/pow3(scalar(nSub_));
            }
        }
        if (a > 0 || g > 0) marks.push_back({celli, a, g});
    }
}


void immersedSpheres::updateBodies(scalar t)
{
    spheres_.set_time(t);
    if (marks_.size() != spheres_.size()) marks_.resize(spheres_.size());

    scalarField& aSum = alphaSum_.primitiveFieldRef();
    scalarField& wSum = weightSum_.primitiveFieldRef();
    scalarField& gSum = geomSum_.primitiveFieldRef();
    vectorField& us = Us_.primitiveFieldRef();
    aSum = 0;
    wSum = 0;
    gSum = 0;
    us = Zero;
    const bool linear = (forcing_ == "linearWall");
    const vectorField& C = mesh_.C().primitiveField();

    for (std::size_t k = 0; k < spheres_.size(); ++k)
    {
        markSphere(k);
        const auto& s = spheres_.spheres()[k];
        for (auto& m : marks_[k])
        {
            // weight of sphere k in this cell: its coefficient (capped) or its fraction
            m.w = linear ? min(m.g, 1e30) : m.alpha;
            aSum[m.cell] += m.alpha;
            gSum[m.cell] = min(gSum[m.cell] + m.g, GREAT);
            wSum[m.cell] += m.w;
            us[m.cell] += m.w*toVec(s.rigid_velocity(toArr(C[m.cell])));
        }
    }
    forAll(wSum, celli)
    {
        if (wSum[celli] > 0) us[celli] /= wSum[celli];
    }
    alpha_.primitiveFieldRef() = min(aSum, scalar(1));
    alpha_.correctBoundaryConditions();
    alphaSum_.correctBoundaryConditions();
    Us_.correctBoundaryConditions();
}


void immersedSpheres::addForcing(fvVectorMatrix& UEqn)
{
    const scalarField A(UEqn.A()().primitiveField());
    const scalar cap = alphaMax_/(1 - alphaMax_);
    if (forcing_ == "linearWall")
    {
        // lambda = nu g, at most cap A (cells whose centre is inside the body)
        lambda_.primitiveFieldRef() = min(nu_*geomSum_.primitiveField(), cap*A);
    }
    else
    {
        // lambda = A alpha/(1 - alpha): the implicit form of U = (1-alpha) U* + alpha U_s
        const scalarField a(min(alpha_.primitiveField(), alphaMax_));
        lambda_.primitiveFieldRef() = A*a/(1 - a);
    }
    lambda_.correctBoundaryConditions();

    UEqn += fvm::Sp(lambda_, UEqn.psi());
    UEqn -= lambda_*Us_;
}


void immersedSpheres::updateLoads(const volVectorField& U, scalar rhoF, scalar dt)
{
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V().field();
    const scalarField& wSum = weightSum_.primitiveField();
    const scalarField& lam = lambda_.primitiveField();
    const vectorField& u = U.primitiveField();
    const vectorField& us = Us_.primitiveField();

    if (prevP_.size() != spheres_.size())
    {
        prevP_.assign(spheres_.size(), Zero);
        prevL_.assign(spheres_.size(), Zero);
        havePrev_ = false;
    }

    for (std::size_t k = 0; k < spheres_.size(); ++k)
    {
        auto& s = spheres_.spheres()[k];
        const point X(s.x[0], s.x[1], s.x[2]);
        vector F(Zero), T(Zero);
        for (const auto& m : marks_[k])
        {
            const label celli = m.cell;
            if (wSum[celli] <= 0) continue;
            const vector f = (m.w/wSum[celli])*lam[celli]*(u[celli] - us[celli])*V[celli];
            F += f;
            T += (C[celli] - X) ^ f;
        }
        reduce(F, sumOp<vector>());
        reduce(T, sumOp<vector>());
        F *= rhoF;
        T *= rhoF;

        // internal fluid moving rigidly with the sphere (Uhlmann 2005):
        // + rho V dv/dt and + rho (2/5) r^2 V domega/dt
        const scalar Vs = constant::mathematical::pi*pow3(s.d)/6;
        const vector P = Vs*toVec(s.v);
        const vector L = 0.4*sqr(s.radius())*Vs*toVec(s.omega);
        if (havePrev_ && dt > 0)
        {
            F += rhoF*(P - prevP_[k])/dt;
            T += rhoF*(L - prevL_[k])/dt;
        }
        prevP_[k] = P;
        prevL_[k] = L;
        s.force = toArr(F);
        s.torque = toArr(T);
    }
    havePrev_ = true;
}


void immersedSpheres::writeLoads(scalar t)
{
    if (!Pstream::master()) return;
    if (!out_)
    {
        const fileName dir =
            mesh_.time().rootPath()/mesh_.time().globalCaseName()/"postProcessing"/"rodIbFoam";
        mkDir(dir);
        out_.reset(new std::ofstream(dir/"sphereForces.csv"));
        hsrod::calib::SphereSet::write_force_header(*out_);
    }
    spheres_.write_forces(*out_, t);
    out_->flush();
}


vector immersedSpheres::stokesVelocity(const point& x, label k, const vector& Uinf) const
{
    // u = U - (3a/4)(U/r + (U.r) r/r^3) - (a^3/4)(U/r^3 - 3 (U.r) r/r^5)
    const auto& s = spheres_.spheres()[k];
    const vector rv = x - toVec(s.x);
    const scalar r = mag(rv);
    const scalar a = s.radius();
    if (r < a) return toVec(s.v);
    const scalar Ur = Uinf & rv;
    return Uinf
        - 0.75*a*(Uinf/r + Ur*rv/pow3(r))
        - 0.25*pow3(a)*(Uinf/pow3(r) - 3*Ur*rv/pow5(r));
}


void immersedSpheres::applyFarField(volVectorField& U) const
{
    if (!dict_.found("farField")) return;
    const dictionary& ff = dict_.subDict("farField");
    const word type = ff.get<word>("type");
    if (type != "stokes" && type != "slitPoiseuille")
    {
        FatalIOErrorInFunction(ff) << "farField type " << type
            << " unknown (stokes, slitPoiseuille)" << exit(FatalIOError);
    }
    const vector Uinf = ff.get<vector>("Uinf");
    const label k = ff.lookupOrDefault<label>("sphere", 0);
    const wordRes patches(ff.get<wordRes>("patches"));
    // slitPoiseuille: undisturbed plane Poiseuille flow between resting
    // walls z = z0 and z = z1 with gap-mean velocity Uinf (in-plane):
    // u(z) = 6 Uinf (z - z0)(z1 - z)/(z1 - z0)^2
    scalar z0 = 0, z1 = 1;
    if (type == "slitPoiseuille")
    {
        z0 = ff.get<scalar>("z0");
        z1 = ff.get<scalar>("z1");
        if (!(z1 > z0))
        {
            FatalIOErrorInFunction(ff) << "farField slitPoiseuille needs z1 > z0 (got z0 "
                << z0 << ", z1 " << z1 << ")" << exit(FatalIOError);
        }
    }
    auto& bf = U.boundaryFieldRef();
    forAll(bf, patchi)
    {
        if (!patches.match(mesh_.boundary()[patchi].name())) continue;
        const vectorField& Cf = mesh_.boundary()[patchi].Cf();
        vectorField val(Cf.size());
        forAll(Cf, facei)
        {
            if (type == "stokes")
            {
                val[facei] = stokesVelocity(Cf[facei], k, Uinf);
            }
            else
            {
                const scalar z = Cf[facei].z();
                val[facei] = 6*Uinf*max(scalar(0), (z - z0)*(z1 - z))/sqr(z1 - z0);
            }
        }
        bf[patchi] == val;
    }
    if (type == "stokes")
    {
        Info<< "farField: exact Stokes velocity around sphere " << k << " on patches "
            << patches << nl;
    }
    else
    {
        Info<< "farField: plane Poiseuille flow, mean " << Uinf << " between z = " << z0
            << " and " << z1 << " on patches " << patches << nl;
    }
}

} // namespace hsrodFoam
