/*---------------------------------------------------------------------------*\
 hsrod calibration, immersed spheres: far-field boundary velocities (exact
 Stokes flow around one sphere, undisturbed plane Poiseuille flow of a slit).
\*---------------------------------------------------------------------------*/
#include "immersedSpheres.H"
#include "vec3Conversion.H"

using namespace Foam;

namespace hsrodFoam
{

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
