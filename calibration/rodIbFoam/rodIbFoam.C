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
#include "rodIbFoamIncludes.H"

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
    #include "createFields.H"
    #include "readCouplingControls.H"
    #include "createDemCoupling.H"

    ib.updateBodies(runTime.value());
    ib.applyFarField(U);

    #include "createMomentumExchange.H"
    #include "checkInputAndReport.H"
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

    #include "readSteadyControls.H"
    #include "createRodMeasures.H"
    #include "createPatchFluxOutput.H"
    #include "readControls.H"

    Info<< nl << "Starting time loop" << nl << endl;
    const clock_t cpu0 = std::clock();
    label nIter = 0;

    while (runTime.run())
    {
        #include "adjustDeltaT.H"

        ++runTime;
        ++nIter;
        Info<< "Time = " << runTime.timeName() << "  Courant " << CoNum << nl;

        #include "advanceDem.H"
        ib.updateBodies(runTime.value());

        scalar resU = 0, resP = 0;
        bool first = true;
        while (pimple.loop())
        {
            #include "UEqn.H"
            while (pimple.correct())
            {
                #include "pEqn.H"
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
        #include "writePatchFlux.H"

        const scalar divErr = runTime.deltaTValue()
            *mag(fvc::div(phi))().weightedAverage(mesh.V()).value();
        Info<< "continuity error (dt-weighted mean |div U|) = " << divErr << nl;

        #include "checkSteadyState.H"
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
