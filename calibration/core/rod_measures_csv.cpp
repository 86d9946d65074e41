// hsrod calibration: rod measures as CSV (see rod_measures_csv.h).
#include "rod_measures_csv.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <stdexcept>

#include <Eigen/Core>

#include "rod/rod_measures.h"

namespace hsrod::calib {

std::vector<RodMeasures> measure_rods(const std::vector<Sphere>& spheres, const RodMeasureSettings& s) {
  if (!(s.channel_width > 0.0) || s.section_size < 1)
    throw std::invalid_argument("rod measures need a channel width W > 0 and section size >= 1");
  std::map<long, std::vector<const Sphere*>> rods;
  for (const auto& sp : spheres) rods[sp.mol].push_back(&sp);
  std::vector<RodMeasures> out;
  for (auto& [mol, members] : rods) {
    std::sort(members.begin(), members.end(), [](const Sphere* a, const Sphere* b) { return a->id < b->id; });
    RodMeasures m;
    m.rod = mol;
    m.n_spheres = static_cast<int>(members.size());
    double w = 0.0;
    for (const Sphere* p : members) {
      const double wi = p->d * p->d * p->d;  // equal density: mass ~ d^3
      w += wi;
      for (int k = 0; k < 3; ++k) {
        m.com[k] += wi * p->x[k];
        m.vel[k] += wi * p->v[k];
      }
    }
    for (int k = 0; k < 3; ++k) {
      m.com[k] /= w;
      m.vel[k] /= w;
    }
    std::vector<Eigen::Vector2d> centres;
    const int nsec = m.n_spheres / s.section_size;
    for (int i = 0; i < nsec; ++i) {
      Eigen::Vector2d c(0, 0);
      for (int k = 0; k < s.section_size; ++k) {
        const Sphere* p = members[i * s.section_size + k];
        c += Eigen::Vector2d(p->x[0], p->x[1]);
      }
      centres.push_back(c / s.section_size);
    }
    if (nsec >= 2) {
      double path = 0.0;  // L_Rod = N d: N x mean centre distance
      for (int i = 1; i < nsec; ++i) path += (centres[i] - centres[i - 1]).norm();
      const double length = path * nsec / (nsec - 1);
      m.angle_deg = hsrod::rod_angle_eq1(centres.front(), centres.back()) * 180.0 / 3.14159265358979323846;
      m.deflection = hsrod::relative_deflection_eq2(centres.front(), centres.back(), centres, length);
    }
    m.lateral = (m.com[1] - s.channel_centre) / s.channel_width;
    if (s.mean_velocity > 0.0) m.vx_over_u = m.vel[0] / s.mean_velocity;
    out.push_back(m);
  }
  return out;
}

void write_rod_measures_header(std::ostream& os) {
  os << "# paper measures per rod and coupling interval (Braesel et al. 2024 eqs. 1-2); SI\n"
        "t,rod,n_spheres,x_com,y_com,z_com,vx,vy,angle_deg,deflection,lateral_over_W,vx_over_U\n";
}

void write_rod_measures(std::ostream& os, double t, const std::vector<RodMeasures>& rods) {
  const auto old = os.precision(10);
  for (const auto& m : rods) {
    os << t << ',' << m.rod << ',' << m.n_spheres << ',' << m.com[0] << ',' << m.com[1] << ',' << m.com[2]
       << ',' << m.vel[0] << ',' << m.vel[1] << ',' << m.angle_deg << ',' << m.deflection << ','
       << m.lateral << ',' << m.vx_over_u << '\n';
  }
  os.precision(old);
}

}  // namespace hsrod::calib
