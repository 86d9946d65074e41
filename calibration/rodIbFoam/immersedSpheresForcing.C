/*---------------------------------------------------------------------------*\
 hsrod calibration, immersed spheres: the implicit forcing of the momentum
 equation and the loads on the spheres from the momentum correction.
\*---------------------------------------------------------------------------*/
#include "immersedSpheres.H"
#include "vec3Conversion.H"

using namespace Foam;

namespace hsrodFoam
{

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
        out_.reset(new std::ofstream(outputDir(mesh_.time())/"sphereForces.csv"));
        hsrod::calib::SphereSet::write_force_header(*out_);
    }
    spheres_.write_forces(*out_, t);
    out_->flush();
}

} // namespace hsrodFoam
