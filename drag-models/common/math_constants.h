// Constants shared by all parts of drag-models (one definition each).
#pragma once

namespace hsrod {

constexpr double kPi = 3.14159265358979323846;  // pi [-]

// Mid-plane over gap-averaged velocity of the parabolic (Poiseuille) gap
// profile u(z) = 6 U (z/H)(1 - z/H): u(H/2) = 3/2 U [-].
constexpr double kMidplaneFactor = 1.5;

}  // namespace hsrod
