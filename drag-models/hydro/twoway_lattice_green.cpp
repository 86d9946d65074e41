#include "hydro/twoway_lattice_green.h"

#include "hydro/peskin_kernel.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace hsrod {

Eigen::Vector2d lattice_node_position(const Eigen::Vector2i& doubled, const Eigen::Vector2d& anchor, double h) {
  return anchor + 0.5 * h * doubled.cast<double>();
}

LatticeFootprint lattice_footprint(const Eigen::Vector2d& centre, const Eigen::Vector2d& anchor, double h,
                                   double w, const ChannelGeometry* geometry) {
  LatticeFootprint f;
  const double radius = 2.0 * std::sqrt(2.0) * w;  // as BrinkmanWindow::nodes_near in the window model
  for (int a = 0; a < 2; ++a) {
    // Component a's nodes: doubled coordinates (2i + a, 2j + 1 - a).
    const double ox = 0.5 * a, oy = 0.5 * (1 - a);
    const int i0 = static_cast<int>(std::floor((centre.x() - radius - anchor.x()) / h - ox));
    const int i1 = static_cast<int>(std::ceil((centre.x() + radius - anchor.x()) / h - ox));
    const int j0 = static_cast<int>(std::floor((centre.y() - radius - anchor.y()) / h - oy));
    const int j1 = static_cast<int>(std::ceil((centre.y() + radius - anchor.y()) / h - oy));
    double total = 0.0;
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const Eigen::Vector2i doubled(2 * i + a, 2 * j + 1 - a);
        const Eigen::Vector2d p = lattice_node_position(doubled, anchor, h);
        if ((p - centre).norm() >= radius) continue;
        const Eigen::Vector2d r = (p - centre) / w;
        const double weight = peskin_kernel(r.x()) * peskin_kernel(r.y());
        if (weight <= 0.0) continue;
        if (geometry && !(geometry->signed_distance(p.x(), p.y()) > 1e-6 * h)) continue;
        f.nodes[a].push_back(doubled);
        f.weights[a].push_back(weight);
        total += weight;
      }
    for (double& weight : f.weights[a]) weight /= total;
  }
  return f;
}

LatticeGreenTable::LatticeGreenTable(const BrinkmanWindow& window, double kernel_width, double reach)
    : h_(window.lattice().h), kernel_width_(kernel_width), reach_(reach) {
  half_ = static_cast<int>(std::ceil(2.0 * reach / h_)) + 1;
  const int side = 2 * half_ + 1;
  for (auto& per_source : table_)
    for (auto& t : per_source) t.assign(static_cast<std::size_t>(side) * side, std::numeric_limits<double>::quiet_NaN());
  // Doubled coordinates of the window's nodes (faces at multiples of h).
  const auto& nodes = window.nodes();
  std::vector<Eigen::Vector2i> doubled(nodes.size());
  int source[2] = {-1, -1};
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Eigen::Vector2d q = 2.0 * nodes[k].position / h_;
    doubled[k] = Eigen::Vector2i(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
    const int a = nodes[k].component;
    if (doubled[k] == Eigen::Vector2i(a, 1 - a)) source[a] = static_cast<int>(k);
  }
  if (source[0] < 0 || source[1] < 0) throw std::invalid_argument("LatticeGreenTable: no source node at the origin");
  Eigen::MatrixXd forces = Eigen::MatrixXd::Zero(window.unknowns(), 2);
  forces(source[0], 0) = forces(source[1], 1) = 1.0;
  const Eigen::MatrixXd velocity = window.solve(forces);
  for (int b = 0; b < 2; ++b) {
    const Eigen::Vector2i at = doubled[source[b]];
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const Eigen::Vector2i offset = doubled[k] - at;
      if (offset.cwiseAbs().maxCoeff() > half_) continue;
      // Only nodes of the uniform zone are on the lattice: their position is exact in h / 2.
      if ((2.0 * nodes[k].position / h_ - doubled[k].cast<double>()).norm() > 1e-6) continue;
      table_[b][nodes[k].component][static_cast<std::size_t>(offset.x() + half_) * side + offset.y() + half_] =
          velocity(static_cast<Eigen::Index>(k), b);
    }
  }
}

bool LatticeGreenTable::covers(const std::vector<Eigen::Vector3d>& centres) const {
  double widest = 0.0;
  for (const auto& a : centres)
    for (const auto& b : centres) widest = std::max(widest, (a - b).head<2>().cwiseAbs().maxCoeff());
  return widest + 4.0 * std::sqrt(2.0) * kernel_width_ + h_ <= reach_;
}

Eigen::Matrix2d LatticeGreenTable::pair(const LatticeFootprint& fi, const LatticeFootprint& fj) const {
  // The table entry of each node pair's offset, with the range check once
  // per footprint pair (the largest offset is that of the footprints'
  // bounding boxes) and the check for untabulated offsets on the sum (a NaN
  // entry makes it NaN).
  const int side = 2 * half_ + 1;
  Eigen::Matrix2d m;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const auto& ni = fi.nodes[a];
      const auto& nj = fj.nodes[b];
      if (!ni.empty() && !nj.empty()) {
        Eigen::Vector2i lo_i = ni.front(), hi_i = ni.front(), lo_j = nj.front(), hi_j = nj.front();
        for (const auto& p : ni) {
          lo_i = lo_i.cwiseMin(p);
          hi_i = hi_i.cwiseMax(p);
        }
        for (const auto& p : nj) {
          lo_j = lo_j.cwiseMin(p);
          hi_j = hi_j.cwiseMax(p);
        }
        if ((hi_i - lo_j).cwiseAbs().maxCoeff() > half_ || (lo_i - hi_j).cwiseAbs().maxCoeff() > half_)
          throw std::out_of_range("LatticeGreenTable: offset beyond the table");
      }
      // Entry of offset (dx, dy): centre + dx * side + dy.
      const double* centre = table_[b][a].data() + static_cast<std::size_t>(half_) * side + half_;
      const double* wi = fi.weights[a].data();
      const double* wj = fj.weights[b].data();
      double sum = 0.0;
      for (std::size_t k = 0; k < ni.size(); ++k) {
        const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(ni[k].x()) * side + ni[k].y();
        for (std::size_t l = 0; l < nj.size(); ++l)
          sum += wi[k] * wj[l] * centre[at - (static_cast<std::ptrdiff_t>(nj[l].x()) * side + nj[l].y())];
      }
      if (std::isnan(sum)) throw std::out_of_range("LatticeGreenTable: offset not tabulated");
      m(a, b) = sum;
    }
  return m;
}

Eigen::MatrixXd LatticeGreenTable::mobility(const std::vector<Eigen::Vector3d>& centres,
                                            const Eigen::Vector2d& anchor) const {
  const int n = static_cast<int>(centres.size());
  std::vector<LatticeFootprint> prints;
  prints.reserve(n);
  for (const auto& c : centres) prints.push_back(footprint(c, anchor));
  Eigen::MatrixXd m(2 * n, 2 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m.block<2, 2>(2 * i, 2 * j) = pair(prints[i], prints[j]);
  return m;
}

}  // namespace hsrod
