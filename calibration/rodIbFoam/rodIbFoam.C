/*---------------------------------------------------------------------------*\
 rodIbFoam - hsrod's resolved reference solver.

 Incompressible, laminar, transient PIMPLE (or steady pseudo-time SIMPLE(C)
 with ddtSchemes steadyState) flow with a direct-forcing immersed boundary
 for rigid spheres (immersedSpheres.H). Kinematic pressure p [m^2/s^2].

   d(U)/dt + div(phi U) - div(nu grad U) = -grad p - lambda (U - U_s)
   div(U) = 0

 Inputs (case directory):
   constant/transportProperties      nu [m^2/s], rho [kg/m^3] (loads in N),
                                     creepingFlow yes|no (drop convection)
   constant/immersedBoundaryProperties  spheres file, motion mode, options
   system/fvSolution PIMPLE          usual entries, plus
                                     steadyTolerance { U 1e-7; p 1e-6; }
                                     (steady runs stop when initial
                                     residuals fall below these)
 Coupled mode (motion coupled): LIGGGHTS moves the spheres, one CFD step per
 coupling interval; momentum exchange `exchange explicit|semiImplicit`
 (momentum_exchange.h: implicit drag on the DEM side plus virtual mass
 `virtualMassCoeff` [-], default: the estimated acceleration reaction
 1/2 + forced shell + Basset impulse of one interval; `dragFactor` [-]).
 Outputs: postProcessing/rodIbFoam/sphereForces.csv (load on each sphere),
          postProcessing/rodIbFoam/rodMeasures.csv (coupled mode with
          `rodMeasures { channelWidth W; channelCentre y; meanVelocity U; }`:
          the paper's eq. 1/2 angle, deflection, lateral position / W,
          velocity / U per rod and coupling interval),
          postProcessing/rodIbFoam/patchFlux.csv (volumetric flux per patch,
          m^3/s), fields alphaSolid, U, p at write times.
\*---------------------------------------------------------------------------*/
#include "fvCFD.H"
#include "pimpleControl.H"
#include "immersedSpheres.H"

#include "momentum_exchange.h"
#include "rod_measures_csv.h"
#include "load_extrapolation.h"

#include <fstream>
#include <iomanip>
#include <memory>

#ifdef HSROD_WITH_DEM_COUPLING
#include <mpi.h>
#include "dem_coupling.h"   // LIGGGHTS behind a pimpl: no LIGGGHTS types here
#endif

int main(int argc, char* argv[])
{
    argList::addNote
    (
        "Transient/steady incompressible flow around immersed rigid spheres"
        " (direct forcing); writes sphere loads as CSV."
    );
    argList::addBoolOption("checkOnly", "check the input, print the report and stop");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    pimpleControl pimple(mesh);

    IOdictionary transportProperties
    (
        IOobject("transportProperties", runTime.constant(), mesh,
                 IOobject::MUST_READ_IF_MODIFIED, IOobject::NO_WRITE)
    );
    const dimensionedScalar nu("nu", dimViscosity, transportProperties);
    const scalar rhoF = transportProperties.get<scalar>("rho");
    const bool creeping = transportProperties.lookupOrDefault<bool>("creepingFlow", false);

    Info<< "Reading field p" << nl;
    volScalarField p
    (
        IOobject("p", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    );
    Info<< "Reading field U" << nl;
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE),
        mesh
    );
    #include "createPhi.H"

    label pRefCell = 0;
    scalar pRefValue = 0;
    setRefCell(p, pimple.dict(), pRefCell, pRefValue);
    mesh.setFluxRequired(p.name());

    hsrodFoam::immersedSpheres ib(mesh, U, nu);

    // ---- coupled mode: LIGGGHTS moves the spheres (fix couple/cfd) ---------
    const bool coupled = ib.spheres().motion() == hsrod::calib::MotionMode::Coupled;
    label nDem = 0;
    scalar dtDem = 0;
    scalar rhoP = 0;                 // particle density from the DEM [kg/m^3]
    bool semiImplicit = false;       // momentum exchange (momentum_exchange.h)
    scalar virtualMassCoeff = 0;     // C_v [-]
    scalar dragFactor = 1;           // K_d [-]
    if (coupled)
    {
        const word ex = ib.dict().lookupOrDefault<word>("exchange", "explicit");
        if (ex != "explicit" && ex != "semiImplicit")
        {
            FatalIOErrorInFunction(ib.dict())
                << "exchange " << ex << " unknown; use explicit or semiImplicit"
                << exit(FatalIOError);
        }
        semiImplicit = (ex == "semiImplicit");
        dragFactor = ib.dict().lookupOrDefault<scalar>("dragFactor", 1.0);
        if (!(dragFactor > 0))
        {
            FatalIOErrorInFunction(ib.dict()) << "dragFactor must be > 0" << exit(FatalIOError);
        }
    }
#ifdef HSROD_WITH_DEM_COUPLING
    std::unique_ptr<hsrod::calib::DemCoupling> dem;
#endif
    if (coupled)
    {
#ifdef HSROD_WITH_DEM_COUPLING
        const dictionary& ibDict = ib.dict();
        const fileName script =
            runTime.rootPath()/runTime.globalCaseName()/ibDict.get<fileName>("demInput");
        nDem = ibDict.get<label>("couplingInterval");
        if (!Pstream::parRun())
        {
            UPstream::initNull();   // LIGGGHTS needs MPI also in serial runs
        }
        MPI_Comm comm = MPI_COMM_WORLD;
        dem.reset
        (
            new hsrod::calib::DemCoupling
            (
                &comm, script, ibDict.lookupOrDefault<bool>("demScreen", false)
            )
        );
        dtDem = dem->timestep();
        // one CFD step = one coupling interval of nDem DEM steps
        if (nDem < 1 || mag(nDem*dtDem - runTime.deltaTValue()) > 1e-6*runTime.deltaTValue())
        {
            FatalErrorInFunction
                << "coupling interval mismatch: couplingInterval " << nDem
                << " x DEM step " << dtDem << " s = " << nDem*dtDem
                << " s must equal the CFD step deltaT " << runTime.deltaTValue() << " s"
                << exit(FatalError);
        }
        dem->pull(ib.spheres());
        // the DEM input must carry the force fix of the chosen exchange
        {
            const int nImplicit = dem->count_fix_style("couple/cfd/force/implicit");
            const int nExplicit = dem->count_fix_style("couple/cfd/force");
            if (semiImplicit && nImplicit != 1)
            {
                FatalIOErrorInFunction(ibDict)
                    << "exchange semiImplicit needs exactly one"
                    << " 'fix ... couple/cfd/force/implicit' in " << script
                    << " (found " << nImplicit << "; explicit couple/cfd/force: " << nExplicit
                    << "); regenerate the case or set exchange explicit" << exit(FatalIOError);
            }
            if (!semiImplicit && nExplicit != 1)
            {
                FatalIOErrorInFunction(ibDict)
                    << "exchange explicit needs exactly one 'fix ... couple/cfd/force' in "
                    << script << " (found " << nExplicit << ")" << exit(FatalIOError);
            }
            if (semiImplicit && dem->count_fix_style("couple/cfd/torque/implicit") != 1)
            {
                WarningInFunction
                    << "no fix couple/cfd/torque/implicit in " << script
                    << ": the spin response is held over the coupling interval"
                    << " (explicit; unstable for dt_c > 0.6 tau_p)" << nl;
            }
        }
        const auto rhoRange = dem->density_range();
        rhoP = rhoRange.first;
        if (rhoRange.second > 1.001*rhoRange.first)
        {
            Info<< "coupled: particle densities " << rhoRange.first << " to "
                << rhoRange.second << " kg/m^3; criteria use the lightest" << nl;
        }
        if (ibDict.found("rhoParticle")
         && mag(ibDict.get<scalar>("rhoParticle") - rhoP) > 1e-3*rhoP)
        {
            FatalIOErrorInFunction(ibDict)
                << "rhoParticle " << ibDict.get<scalar>("rhoParticle")
                << " kg/m^3 disagrees with the DEM particles' density " << rhoP
                << " kg/m^3 (rmass / (pi d^3/6)); fix the scene" << exit(FatalIOError);
        }
        Info<< "coupled to LIGGGHTS: " << label(ib.spheres().size()) << " spheres, "
            << nDem << " DEM steps of " << dtDem << " s per CFD step" << nl;
#else
        FatalErrorInFunction
            << "motion coupled needs rodIbFoam built with LIGGGHTS"
            << " (libliggghts-dev; CMake HSROD_CALIBRATION_DEM_COUPLING)"
            << exit(FatalError);
#endif
    }

    ib.updateBodies(runTime.value());
    ib.applyFarField(U);

    std::unique_ptr<hsrod::calib::MomentumExchange> exchange;
    if (coupled)
    {
        scalar dMin = GREAT;
        for (const auto& s : ib.spheres().spheres()) dMin = min(dMin, s.d);
        const scalar hS = ib.cellSizeAtSpheres();
        // default C_v: the estimated acceleration reaction of one interval
        // (added mass 1/2 + forced shell + Basset impulse; momentum_exchange.h)
        const scalar c = hsrod::calib::acceleration_reaction_coeff
        (
            dMin, hS, nu.value(), runTime.deltaTValue()
        );
        virtualMassCoeff = semiImplicit
            ? ib.dict().lookupOrDefault<scalar>("virtualMassCoeff", c) : 0;
        if (virtualMassCoeff < 0)
        {
            FatalIOErrorInFunction(ib.dict()) << "virtualMassCoeff must be >= 0" << exit(FatalIOError);
        }
        hsrod::calib::ExchangeSettings es;
        es.semi_implicit = semiImplicit;
        es.virtual_mass_coeff = virtualMassCoeff;
        es.drag_factor = dragFactor;
        es.mu = nu.value()*rhoF;
        es.rho_f = rhoF;
        es.dt_couple = runTime.deltaTValue();
        exchange.reset(new hsrod::calib::MomentumExchange(es));
        Info<< "momentum exchange: " << (semiImplicit ? "semi-implicit" : "explicit");
        if (semiImplicit)
        {
            Info<< " (Ksl = " << dragFactor << " x 3 pi mu d per DEM step, virtual mass "
                << virtualMassCoeff << " rho_f V)";
        }
        Info<< nl;
    }

    // ---- bad input and stability/cost report, before any time is spent ----
    const word ddtName(mesh.ddtScheme("ddt(U)")[0].wordToken());
    const bool steady = (ddtName == "steadyState");
    {
        hsrod::calib::RunParameters rp;
        U.correctBoundaryConditions();   // evaluate e.g. flow-rate inlets
        scalar umax = gMax(mag(U.primitiveField())());
        forAll(U.boundaryField(), patchi)
        {
            if (U.boundaryField()[patchi].size())
            {
                umax = max(umax, max(mag(U.boundaryField()[patchi])));
            }
        }
        reduce(umax, maxOp<scalar>());
        for (const auto& s : ib.spheres().spheres())
        {
            umax = max(umax, std::sqrt(s.v[0]*s.v[0] + s.v[1]*s.v[1] + s.v[2]*s.v[2]));
        }
        rp.u_ref = umax;
        rp.dt = runTime.deltaTValue();
        rp.nu = nu.value();
        rp.rho_f = rhoF;
        rp.steady = steady;
        rp.n_iterations = (runTime.endTime().value() - runTime.startTime().value())/rp.dt;
        rp.n_correctors = pimple.dict().lookupOrDefault<label>("nCorrectors", 1)
            *pimple.dict().lookupOrDefault<label>("nOuterCorrectors", 1);
        rp.momentum_predictor = pimple.dict().lookupOrDefault<bool>("momentumPredictor", true);
        rp.consistent = pimple.dict().lookupOrDefault<bool>("consistent", false);
        rp.dt_dem = dtDem;
        rp.coupling_interval = nDem;
        rp.semi_implicit = semiImplicit;
        rp.virtual_mass_coeff = virtualMassCoeff;
        rp.drag_factor = dragFactor;
        rp.rho_p = rhoP;
        rp.max_courant = runTime.controlDict().lookupOrDefault<scalar>("maxCo", 1.0);
        ib.checkAndReport(rp);
    }
#ifdef HSROD_WITH_DEM_COUPLING
    if (dem && semiImplicit && virtualMassCoeff > 0)
    {
        // the DEM integrates with m_p + m_v from here on
        dem->add_virtual_mass(virtualMassCoeff, rhoF);
    }
#endif
    if (args.found("checkOnly"))
    {
        Info<< "checkOnly: input accepted" << nl << "End" << nl;
        return 0;
    }

    // steady convergence criteria (initial residuals of the first solves)
    const dictionary steadyTol(pimple.dict().subOrEmptyDict("steadyTolerance"));
    const scalar tolU = steadyTol.lookupOrDefault<scalar>("U", 1e-7);
    const scalar tolP = steadyTol.lookupOrDefault<scalar>("p", 1e-6);
    // relative change of the sphere loads per iteration, |F^n - F^n-1| / |F^n|
    const scalar tolF = steadyTol.lookupOrDefault<scalar>("F", 1e-7);
    std::vector<hsrod::calib::Vec3> prevF(ib.spheres().size());
    // optional: stop on the Aitken-extrapolated loads instead of the raw load
    // change (core/load_extrapolation.h): Fextrapolated = tolerance on the
    // change of the extrapolated loads over one window of Fwindow iterations
    std::unique_ptr<hsrod::calib::LoadExtrapolation> loadExtrap;
    const scalar tolFx = steadyTol.lookupOrDefault<scalar>("Fextrapolated", -1);
    if (tolFx > 0)
    {
        scalar dMin = GREAT;
        for (const auto& s : ib.spheres().spheres()) dMin = min(dMin, s.d);
        loadExtrap.reset(new hsrod::calib::LoadExtrapolation
        (
            steadyTol.lookupOrDefault<label>("Fwindow", 10), dMin
        ));
    }

    // rod measures per coupling interval (coupled mode)
    std::unique_ptr<std::ofstream> rodOut;
    hsrod::calib::RodMeasureSettings rodSet;
    if (coupled && ib.dict().found("rodMeasures"))
    {
        const dictionary& rm = ib.dict().subDict("rodMeasures");
        rodSet.channel_width = rm.get<scalar>("channelWidth");
        rodSet.channel_centre = rm.lookupOrDefault<scalar>("channelCentre", 0.5*rodSet.channel_width);
        rodSet.mean_velocity = rm.lookupOrDefault<scalar>("meanVelocity", 0);
        rodSet.section_size = rm.lookupOrDefault<label>("sectionSize", 1);
        if (!(rodSet.channel_width > 0) || rodSet.section_size < 1)
        {
            FatalIOErrorInFunction(rm) << "rodMeasures: need channelWidth > 0, sectionSize >= 1"
                << exit(FatalIOError);
        }
        if (Pstream::master())
        {
            const fileName dir =
                runTime.rootPath()/runTime.globalCaseName()/"postProcessing"/"rodIbFoam";
            mkDir(dir);
            rodOut.reset(new std::ofstream(dir/"rodMeasures.csv"));
            hsrod::calib::write_rod_measures_header(*rodOut);
        }
    }
    auto writeRods = [&](scalar t)
    {
        if (!rodOut) return;
        hsrod::calib::write_rod_measures
        (
            *rodOut, t, hsrod::calib::measure_rods(ib.spheres().spheres(), rodSet)
        );
        rodOut->flush();
    };
    writeRods(runTime.value());

    std::unique_ptr<std::ofstream> fluxOut;
    if (Pstream::master())
    {
        const fileName dir = runTime.rootPath()/runTime.globalCaseName()/"postProcessing"/"rodIbFoam";
        mkDir(dir);
        fluxOut.reset(new std::ofstream(dir/"patchFlux.csv"));
        *fluxOut << "# volumetric flux out of each patch [m^3/s]\nt";
        for (const fvPatch& pp : mesh.boundary()) *fluxOut << ',' << pp.name();
        *fluxOut << '\n';
    }

    // ddtCorr: off by default with moving bodies (the old flux belongs to the
    // old body position; measured: keeping it makes moving-sphere runs diverge)
    const bool useDdtCorr = pimple.dict().lookupOrDefault<bool>
    (
        "ddtCorr",
        ib.spheres().motion() == hsrod::calib::MotionMode::Fixed
    );
    const scalar maxCo = runTime.controlDict().lookupOrDefault<scalar>("maxCo", 1.0);
    const bool adjustTimeStep =
        runTime.controlDict().lookupOrDefault("adjustTimeStep", false) && !steady;
    const scalar maxDeltaT = runTime.controlDict().lookupOrDefault<scalar>("maxDeltaT", GREAT);

    Info<< nl << "Starting time loop" << nl << endl;
    const clock_t cpu0 = std::clock();
    label nIter = 0;

    while (runTime.run())
    {
        // Courant number on the face fluxes (standard definition)
        scalar CoNum = 0;
        {
            const scalarField sumPhi(fvc::surfaceSum(mag(phi))().primitiveField());
            CoNum = 0.5*gMax(sumPhi/mesh.V().field())*runTime.deltaTValue();
        }
        if (adjustTimeStep && CoNum > SMALL)
        {
            const scalar factor = min(min(maxCo/CoNum, 1.2), 1.0 + 0.1*(maxCo/CoNum));
            runTime.setDeltaT(min(factor*runTime.deltaTValue(), maxDeltaT));
        }

        ++runTime;
        ++nIter;
        Info<< "Time = " << runTime.timeName() << "  Courant " << CoNum << nl;

#ifdef HSROD_WITH_DEM_COUPLING
        if (dem)
        {
            // DEM advances one coupling interval with the loads of the last
            // fluid step, then hands over the new sphere states
            dem->run(nDem);
            dem->pull(ib.spheres());
            writeRods(runTime.value());
        }
#endif
        ib.updateBodies(runTime.value());

        scalar resU = 0, resP = 0;
        bool first = true;
        while (pimple.loop())
        {
            tmp<fvVectorMatrix> tUEqn
            (
                creeping
              ? fvm::ddt(U) - fvm::laplacian(nu, U)
              : fvm::ddt(U) + fvm::div(phi, U) - fvm::laplacian(nu, U)
            );
            fvVectorMatrix& UEqn = tUEqn.ref();
            ib.addForcing(UEqn);
            UEqn.relax();

            if (pimple.momentumPredictor())
            {
                const auto perf = solve(UEqn == -fvc::grad(p));
                if (first)
                {
                    // components that carry (almost) no flow have meaningless
                    // normalised residuals: judge only those above 1e-3 max|U|
                    const scalar umag = gMax(mag(U.primitiveField())()) + VSMALL;
                    resU = 0;
                    for (direction i = 0; i < vector::nComponents; ++i)
                    {
                        if (gMax(mag(U.primitiveField().component(i))()) > 1e-3*umag)
                        {
                            resU = max(resU, perf.initialResidual()[i]);
                        }
                    }
                }
            }

            while (pimple.correct())
            {
                // pressure projection of the forced velocity
                volScalarField rAU(1.0/UEqn.A());
                volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p));
                surfaceScalarField phiHbyA("phiHbyA", fvc::flux(HbyA));
                if (useDdtCorr)
                {
                    // Rhie-Chow-type time-derivative flux correction
                    phiHbyA += fvc::interpolate(rAU)*fvc::ddtCorr(U, phi);
                }
                if (p.needReference())
                {
                    adjustPhi(phiHbyA, U, p);
                }

                tmp<volScalarField> rAtU(rAU);
                if (pimple.consistent())
                {
                    // SIMPLEC: 1/(A - sum of neighbour coefficients)
                    rAtU = 1.0/max(1.0/rAU - UEqn.H1(), 0.1/rAU);
                    phiHbyA += fvc::interpolate(rAtU() - rAU)*fvc::snGrad(p)*mesh.magSf();
                    HbyA -= (rAU - rAtU())*fvc::grad(p);
                }
                constrainPressure(p, U, phiHbyA, rAtU());

                while (pimple.correctNonOrthogonal())
                {
                    fvScalarMatrix pEqn(fvm::laplacian(rAtU(), p) == fvc::div(phiHbyA));
                    pEqn.setReference(pRefCell, pRefValue);
                    const auto perf = pEqn.solve(mesh.solver(p.select(pimple.finalInnerIter())));
                    if (first) { resP = perf.initialResidual(); first = false; }
                    if (pimple.finalNonOrthogonalIter())
                    {
                        phi = phiHbyA - pEqn.flux();
                    }
                }
                p.relax();
                U = HbyA - rAtU*fvc::grad(p);
                U.correctBoundaryConditions();
            }
        }

        ib.updateLoads(U, rhoF, steady ? 0 : runTime.deltaTValue());
        ib.writeLoads(runTime.value());
#ifdef HSROD_WITH_DEM_COUPLING
        if (dem)
        {
            dem->push(exchange->loads(ib.spheres().spheres()), Pstream::master(), semiImplicit);
        }
#endif

        // volumetric flux out of each patch [m^3/s]
        {
            List<scalar> flux(mesh.boundary().size(), 0.0);
            forAll(mesh.boundary(), patchi) flux[patchi] = gSum(phi.boundaryField()[patchi]);
            if (fluxOut)
            {
                *fluxOut << std::setprecision(10) << runTime.value();
                for (const scalar f : flux) *fluxOut << ',' << f;
                *fluxOut << '\n';
                fluxOut->flush();
            }
        }

        const scalar divErr = runTime.deltaTValue()
            *mag(fvc::div(phi))().weightedAverage(mesh.V()).value();
        Info<< "continuity error (dt-weighted mean |div U|) = " << divErr << nl;

        scalar dF = 0;
        for (std::size_t k = 0; k < ib.spheres().size(); ++k)
        {
            const auto& F = ib.spheres().spheres()[k].force;
            const vector Fn(F[0], F[1], F[2]);
            const vector Fo(prevF[k][0], prevF[k][1], prevF[k][2]);
            dF = max(dF, mag(Fn - Fo)/(mag(Fn) + VSMALL));
            prevF[k] = F;
        }
        bool loadsConverged = dF < tolF;
        if (loadExtrap)
        {
            std::vector<hsrod::calib::SphereLoad> loads;
            for (const auto& s : ib.spheres().spheres()) loads.push_back({s.force, s.torque});
            loadExtrap->add(loads);
            loadsConverged = loadExtrap->relative_change() < tolFx;
        }
        if (steady && nIter > 2 && resU < tolU && resP < tolP && loadsConverged)
        {
            if (loadExtrap)
            {
                Info<< "extrapolated loads: change over one window "
                    << loadExtrap->relative_change() << " < " << tolFx
                    << ", estimated iteration error of the raw loads "
                    << loadExtrap->relative_remainder() << nl;
                if (Pstream::master())
                {
                    const fileName dir = runTime.rootPath()/runTime.globalCaseName()
                        /"postProcessing"/"rodIbFoam";
                    mkDir(dir);
                    std::ofstream ex(dir/"sphereLoadsExtrapolated.csv");
                    ex << "# Aitken-extrapolated steady loads (core/load_extrapolation.h; SI: N, N m); "
                       << "iterations " << nIter << ", change over one window "
                       << loadExtrap->relative_change() << ", raw-load remainder "
                       << loadExtrap->relative_remainder() << "\n"
                       << "id,Fx,Fy,Fz,Tx,Ty,Tz\n" << std::setprecision(12);
                    const auto xl = loadExtrap->extrapolated();
                    for (std::size_t k = 0; k < xl.size(); ++k)
                    {
                        ex << ib.spheres().spheres()[k].id;
                        for (const double c : xl[k].force) ex << ',' << c;
                        for (const double c : xl[k].torque) ex << ',' << c;
                        ex << '\n';
                    }
                }
            }
            Info<< "steady state reached: initial residuals U " << resU << " < " << tolU
                << ", p " << resP << " < " << tolP << ", load change " << dF << " < " << tolF
                << " after " << nIter << " iterations" << nl;
            runTime.writeAndEnd();
        }
        else
        {
            runTime.write();
        }
        Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s" << nl << endl;
    }

#ifdef HSROD_WITH_DEM_COUPLING
    dem.reset();   // before argList goes: OpenFOAM's exit finalises MPI
#endif
    const scalar cpu = scalar(std::clock() - cpu0)/CLOCKS_PER_SEC;
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    Info<< "rodIbFoam: " << nIter << " iterations, " << nCells << " cells, "
        << cpu << " s CPU, " << cpu/max(label(1), nIter)/max(label(1), nCells)
        << " s per cell-iteration" << nl << "End" << nl;
    return 0;
}
