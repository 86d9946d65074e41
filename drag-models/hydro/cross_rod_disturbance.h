// Level 3 between rods, solved rod by rod (fix rod/implicit `rod_interaction
// lagged` and `iterated`).
//
// Level 3 (nonlocal_model.h) gives the in-plane obstruction forces P of all
// spheres of a scene by one dense solve, (I + zeta_o M) P = zeta_o (c u - v),
// M the pair mobilities (c G blended into the near field). Rods within the
// interaction reach of each other are chained through a suspension (the
// reach, ~115 um at H = 20 um, exceeds the rods' spacing at a few per cent
// area fraction), so the joint solve grows to the whole scene, ~N^2 per
// rod-step. Split M into the blocks of a unit A (a rod, or rods in contact
// stepped together) and those between units: the unit's own solve
//     (I + zeta_o M_AA) P_A = zeta_o (c u_A - v_A - sum_B M_AB P_B)
// is the lone one with the other units' disturbance q_A = sum_B M_AB P_B
// [m/s] as an extra velocity imposed at its spheres. With the held load's
// own near field (M^D, NearFieldAtBeta) the two parts of P are carried
// apart, P = P^D - P^v:
//     P^D_A = R^D_A (c u_A - q^D_A),   P^v_A = R_A (v_A - q^v_A),
//     F_A = F_A^alone(v_A) - R^D_A q^D_A + R_A q^v_A,
// R_A = zeta_o (I + zeta_o M_AA)^-1 and R^D_A its held-load twin. Iterated
// over the units, each with the others' latest P (block Gauss-Seidel on
// P: I + zeta_o M is symmetric positive definite, so the sweeps converge
// to the joint solve, at a rate set by the strongest coupling between
// units; block Jacobi, all units from the last sweep's P, diverges for rods
// side by side within ~2.5 d, tests/drag-models/hydro/test_cross_rod_disturbance.cpp); lagged, q is taken from the previous step's
// P, an explicit coupling whose error is of the order of the change of P
// over one step times the coupling. Pairs of rods farther apart than the
// model's interaction reach (each coupling by less than
// NonlocalRodModel::kInteractionTolerance of a sphere's own obstruction,
// but many of them) are the far field's, hydro/cross_rod_far_field.h.
#pragma once

#include "hydro/hydrodynamic_model.h"
#include "hydro/nonlocal_model.h"

#include <Eigen/Core>

#include <vector>

namespace hsrod {

// One unit solved alone: what its load and its obstruction forces need.
struct UnitObstruction {
  Eigen::MatrixXd friction;          // R = zeta_o (I + zeta_o M_AA)^-1, 2n x 2n in plane [N s/m]
  Eigen::MatrixXd driving;           // R^D, its held-load twin [N s/m]; empty: the same as friction
  Eigen::VectorXd lone_driving;      // c R^D u, 2n [N]: the held obstruction force alone
  Eigen::VectorXd driving_disturbance;   // q^D = sum_B M^D_AB P^D_B, 2n [m/s]
  Eigen::VectorXd velocity_disturbance;  // q^v = sum_B M_AB P^v_B, 2n [m/s]
  const Eigen::MatrixXd& held() const { return driving.size() > 0 ? driving : friction; }
};

// One rod's in-plane obstruction forces and the disturbance it sees, kept
// by the caller per rod (between steps for the lagged coupling).
struct RodObstructionForces {
  Eigen::VectorXd driving;   // P^D, 2n [N]
  Eigen::VectorXd velocity;  // P^v, 2n [N]
  Eigen::VectorXd driving_disturbance, velocity_disturbance;  // q^D, q^v, 2n [m/s]
  // Sized for n spheres: forces kept if they fit (else zero), disturbances zeroed.
  void start(int spheres);
  void clear_disturbance();  // q^D = q^v = 0
};

// out.driving_force (in plane) += -R^D q^D + R q^v: the load of the unit
// alone (evaluate_alone) turned into its load among the other units.
void add_cross_rod_disturbance(const UnitObstruction& unit, RodDrag& out);

// P^D and P^v (2n each) of the unit at its sphere velocities [m/s].
void unit_obstruction_forces(const UnitObstruction& unit, const std::vector<Eigen::Vector3d>& velocities,
                             Eigen::VectorXd& driving, Eigen::VectorXd& velocity);

// The largest change of a sphere's obstruction force P = P^D - P^v from
// `before` to `now`, over the largest |P| of `now` [-]: the iteration's
// measure of convergence.
double obstruction_change(const std::vector<RodObstructionForces>& before,
                          const std::vector<RodObstructionForces>& now);

}  // namespace hsrod
