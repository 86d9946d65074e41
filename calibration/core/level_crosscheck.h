// hsrod calibration: the reduced models' response of a straight row of
// spheres in a slit, in the units of the resolved campaign
// (calibration/tools/campaign_analysis.py), for the cross-check of levels
// 1-4 against rodIbFoam and the calibration tests.
//
// Row of n spheres (diameter d, centre spacing s d) at the mid-plane of a
// slit of gap H = d / beta, far from side walls, along (par) or across
// (perp) a uniform gap-averaged stream of speed U:
//   friction_i = x-force on sphere i when the row translates at -U e_x
//                through fluid at rest, over 3 pi mu d U;
//   driving_i  = x-force on sphere i held in the stream, over 3 pi mu d U;
// R = sum friction_i, D = sum driving_i, lambda = D / R (force-free
// velocity over U), r = lambda_perp / lambda_par.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hydro/confinement_coefficients.h"
#include "hydro/hydrodynamic_model.h"
#include "hydro/near_field_coupling.h"

namespace hsrod::calib {

struct RowResponse {
  std::vector<double> friction_par, friction_perp, driving_par, driving_perp;  // per sphere [-]
  double R_par() const;
  double R_perp() const;
  double D_par() const;
  double D_perp() const;
  double lambda_par() const { return D_par() / R_par(); }
  double lambda_perp() const { return D_perp() / R_perp(); }
  double r() const { return lambda_perp() / lambda_par(); }
};

// model: a registered model name (isotropic, local, nonlocal, twoway);
// near_field: the near-field coupling of levels 3-4 (default: the built-in fit).
RowResponse row_response(const std::string& model, double beta, int n, double spacing,
                         const ConfinementTable& table,
                         const NearFieldCalibration& near_field = NearFieldCalibration::built_in());

// The model of a level as the cross-check evaluates it: levels 3-4
// (nonlocal, twoway) with the given near field, the others from the registry;
// "nonlocal+images", "nonlocal+self_images": level 3 with the walls' images
// (WallReflection::images, self_images).
std::unique_ptr<HydrodynamicModel> make_level_model(const std::string& model, const HydrodynamicParameters& parameters,
                                                    const ConfinementTable& table,
                                                    const NearFieldCalibration& near_field);

// The loads behind a RowResponse, kept so that a fit can change the near
// field on them without re-evaluating the model (calibration/core/near_field_fit.h).
struct RowLoads {
  HydrodynamicParameters parameters;
  double speed = 0.0;   // U [m/s]
  RodGeometry rod[2];   // along (0) and across (1) the flow
  RodDrag still[2];     // in fluid at rest
  RodDrag stream[2];    // in the uniform stream U e_x
};
RowLoads row_loads(const HydrodynamicModel& model, const HydrodynamicParameters& parameters, int n, double spacing);
RowResponse row_response(const RowLoads& loads);
// The units of row_loads (any: the response is dimensionless): d, mu, U.
HydrodynamicParameters row_parameters(double beta);

}  // namespace hsrod::calib
