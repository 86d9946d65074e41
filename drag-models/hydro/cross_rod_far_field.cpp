#include "hydro/cross_rod_far_field.h"

#include "common/math_constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hsrod {

namespace {

// Complex arithmetic written out on (re, im) pairs: std::complex's
// operators check for infinities (__muldc3) at several times the cost.
struct Cx {
  double re, im;
};
inline Cx mul(Cx a, Cx b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline Cx inverse(Cx a) {
  const double n = a.re * a.re + a.im * a.im;
  return {a.re / n, -a.im / n};
}

// Distance between two axis-aligned boxes [m] (0 if they overlap).
double box_gap(double ax0, double ax1, double ay0, double ay1, double bx0, double bx1, double by0, double by1) {
  const double dx = std::max({0.0, bx0 - ax1, ax0 - bx1});
  const double dy = std::max({0.0, by0 - ay1, ay0 - by1});
  return std::hypot(dx, dy);
}

}  // namespace

void CrossRodFarField::set_scene(double viscosity, double gap_height, double reach) {
  if (!(viscosity > 0.0 && gap_height > 0.0 && reach > 0.0))
    throw std::invalid_argument("cross-rod far field: viscosity, gap height and reach must be positive");
  dipole_strength_ = kMidplaneFactor * gap_height / (24.0 * kPi * viscosity);
  reach_ = reach;
}

double CrossRodFarField::truncation_factor(double q) {
  if (!(q >= 0.0 && q < 1.0)) throw std::invalid_argument("cross-rod far field: expansion ratio outside [0, 1)");
  const double P = kOrder;
  return std::pow(q, P + 1.0) * ((P + 2.0) - (P + 1.0) * q) / ((1.0 - q) * (1.0 - q));
}

void CrossRodFarField::build(const std::vector<int>& ids, const std::vector<const RodGeometry*>& rods,
                             const std::vector<const RodObstructionForces*>& forces) {
  if (ids.size() != rods.size() || ids.size() != forces.size())
    throw std::invalid_argument("cross-rod far field: ids, rods and forces differ in number");
  if (dipole_strength_ <= 0.0) throw std::logic_error("cross-rod far field: build before set_scene");
  const int count = static_cast<int>(rods.size());
  ids_ = ids;
  sphere_first_.assign(1, 0);
  x_.clear();
  y_.clear();
  for (auto& channel : f_)
    for (auto& part : channel) part.clear();
  centre_x_.assign(count, 0.0);
  centre_y_.assign(count, 0.0);
  for (int r = 0; r < count; ++r) {
    const RodGeometry& rod = *rods[r];
    const RodObstructionForces& p = *forces[r];
    if (p.driving.size() != 2 * rod.size() || p.velocity.size() != 2 * rod.size())
      throw std::invalid_argument("cross-rod far field: a rod's obstruction forces and spheres differ in number");
    for (int i = 0; i < rod.size(); ++i) {
      x_.push_back(rod.positions[i].x());
      y_.push_back(rod.positions[i].y());
      centre_x_[r] += rod.positions[i].x() / rod.size();
      centre_y_[r] += rod.positions[i].y() / rod.size();
      f_[0][0].push_back(p.driving(2 * i));
      f_[0][1].push_back(p.driving(2 * i + 1));
      f_[1][0].push_back(p.velocity(2 * i));
      f_[1][1].push_back(p.velocity(2 * i + 1));
    }
    sphere_first_.push_back(static_cast<int>(x_.size()));
  }
  rod_order_.resize(count);
  for (int r = 0; r < count; ++r) rod_order_[r] = r;
  boxes_.clear();
  terms_.clear();
  if (count > 0) build_box(0, count);
  id_positions_.resize(count);
  for (int t = 0; t < count; ++t) id_positions_[t] = {ids_[rod_order_[t]], t};
  std::sort(id_positions_.begin(), id_positions_.end());
  const auto twice = std::adjacent_find(id_positions_.begin(), id_positions_.end(),
                                        [](const auto& a, const auto& b) { return a.first == b.first; });
  if (twice != id_positions_.end())
    throw std::invalid_argument("cross-rod far field: rod id " + std::to_string(twice->first) + " given twice");
}

int CrossRodFarField::build_box(int first, int last) {
  Box box;
  box.first = first;
  box.last = last;
  box.x_min = box.y_min = INFINITY;
  box.x_max = box.y_max = -INFINITY;
  for (int t = first; t < last; ++t) {
    const int r = rod_order_[t];
    for (int k = sphere_first_[r]; k < sphere_first_[r + 1]; ++k) {
      box.x_min = std::min(box.x_min, x_[k]);
      box.x_max = std::max(box.x_max, x_[k]);
      box.y_min = std::min(box.y_min, y_[k]);
      box.y_max = std::max(box.y_max, y_[k]);
    }
  }
  const int index = static_cast<int>(boxes_.size());
  boxes_.push_back(box);
  expand(boxes_[index], index);
  if (last - first > kLeafRods) {
    // Halve at the median rod centre along the longer side (ties by id: the
    // same tree on every rank).
    const bool along_x = box.x_max - box.x_min >= box.y_max - box.y_min;
    const std::vector<double>& key = along_x ? centre_x_ : centre_y_;
    const int middle = first + (last - first) / 2;
    std::nth_element(rod_order_.begin() + first, rod_order_.begin() + middle, rod_order_.begin() + last,
                     [&](int a, int b) { return key[a] < key[b] || (key[a] == key[b] && ids_[a] < ids_[b]); });
    const int left = build_box(first, middle);
    const int right = build_box(middle, last);
    boxes_[index].left = left;
    boxes_[index].right = right;
  }
  return index;
}

void CrossRodFarField::expand(Box& box, int index) {
  box.cx = 0.5 * (box.x_min + box.x_max);
  box.cy = 0.5 * (box.y_min + box.y_max);
  box.radius = 0.0;
  for (int t = box.first; t < box.last; ++t) {
    const int r = rod_order_[t];
    for (int k = sphere_first_[r]; k < sphere_first_[r + 1]; ++k)
      box.radius = std::max(box.radius, std::hypot(x_[k] - box.cx, y_[k] - box.cy));
  }
  const double scale = box.radius > 0.0 ? 1.0 / box.radius : 1.0;
  const std::size_t stride = 2 * (kOrder + 1);
  terms_.resize(static_cast<std::size_t>(index + 1) * 2 * stride, 0.0);
  for (int c = 0; c < 2; ++c) {
    double* a = &terms_[(static_cast<std::size_t>(index) * 2 + c) * stride];
    box.force_sum[c] = 0.0;
    for (int t = box.first; t < box.last; ++t) {
      const int r = rod_order_[t];
      for (int k = sphere_first_[r]; k < sphere_first_[r + 1]; ++k) {
        const Cx d{(x_[k] - box.cx) * scale, (y_[k] - box.cy) * scale};
        Cx w{f_[c][0][k], f_[c][1][k]};  // f (d / rho)^p
        box.force_sum[c] += std::hypot(w.re, w.im);
        for (int p = 0; p <= kOrder; ++p) {
          a[2 * p] += w.re;
          a[2 * p + 1] += w.im;
          w = mul(w, d);
        }
      }
    }
    for (int p = 0; p <= kOrder; ++p) {  // (p + 1) a_p: the derivative's factor
      a[2 * p] *= p + 1;
      a[2 * p + 1] *= p + 1;
    }
  }
}

double CrossRodFarField::add_disturbance(const RodGeometry& target, const std::vector<int>& excluded,
                                         RodObstructionForces& target_forces) const {
  const int n = target.size();
  if (target_forces.driving_disturbance.size() != 2 * n || target_forces.velocity_disturbance.size() != 2 * n)
    throw std::invalid_argument("cross-rod far field: the target's disturbance and spheres differ in number");
  if (boxes_.empty() || n == 0) return 0.0;
  double tx0 = INFINITY, tx1 = -INFINITY, ty0 = INFINITY, ty1 = -INFINITY, cx = 0.0, cy = 0.0;
  for (const auto& p : target.positions) {
    tx0 = std::min(tx0, p.x());
    tx1 = std::max(tx1, p.x());
    ty0 = std::min(ty0, p.y());
    ty1 = std::max(ty1, p.y());
    cx += p.x() / n;
    cy += p.y() / n;
  }
  double target_radius = 0.0;
  for (const auto& p : target.positions) target_radius = std::max(target_radius, std::hypot(p.x() - cx, p.y() - cy));
  // sum_k f_k / (z - z_k)^2 per target sphere and channel, and its truncation bound
  std::vector<Cx> sum(2 * n, Cx{0.0, 0.0});
  double bound[2] = {0.0, 0.0};  // per channel, the same for every target sphere
  const std::size_t stride = 2 * (kOrder + 1);
  // The excluded rods' places in tree order: a box holding one is opened,
  // never summed whole, so that no pair coupled exactly is added again.
  std::vector<int> excluded_places;
  for (int id : excluded) {
    const auto at = std::lower_bound(id_positions_.begin(), id_positions_.end(), std::make_pair(id, -1));
    if (at != id_positions_.end() && at->first == id) excluded_places.push_back(at->second);
  }
  std::sort(excluded_places.begin(), excluded_places.end());
  const auto holds_excluded = [&](const Box& box) {
    const auto at = std::lower_bound(excluded_places.begin(), excluded_places.end(), box.first);
    return at != excluded_places.end() && *at < box.last;
  };
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Box& box = boxes_[stack.back()];
    const int index = stack.back();
    stack.pop_back();
    const double gap = box_gap(tx0, tx1, ty0, ty1, box.x_min, box.x_max, box.y_min, box.y_max);
    const double distance = std::hypot(cx - box.cx, cy - box.cy) - target_radius;
    if (gap > reach_ && distance > 0.0 && box.radius <= kOpening * distance && !holds_excluded(box)) {
      // every target sphere is >= `distance` from the centre: q <= radius / distance there
      const double tail = truncation_factor(box.radius / distance) / (distance * distance);
      for (int c = 0; c < 2; ++c) bound[c] += box.force_sum[c] * tail;
      for (int i = 0; i < n; ++i) {
        const Cx z{target.positions[i].x() - box.cx, target.positions[i].y() - box.cy};
        const Cx inv = inverse(z);
        const Cx w = mul(Cx{box.radius, 0.0}, inv);
        for (int c = 0; c < 2; ++c) {
          const double* a = &terms_[(static_cast<std::size_t>(index) * 2 + c) * stride];
          Cx acc{a[2 * kOrder], a[2 * kOrder + 1]};
          for (int p = kOrder - 1; p >= 0; --p) {
            acc = mul(acc, w);
            acc.re += a[2 * p];
            acc.im += a[2 * p + 1];
          }
          const Cx s = mul(acc, mul(inv, inv));
          sum[2 * i + c].re += s.re;
          sum[2 * i + c].im += s.im;
        }
      }
    } else if (box.left >= 0) {
      stack.push_back(box.right);
      stack.push_back(box.left);
    } else {
      for (int t = box.first; t < box.last; ++t) {
        const int r = rod_order_[t];
        if (std::binary_search(excluded.begin(), excluded.end(), ids_[r])) continue;
        for (int i = 0; i < n; ++i) {
          for (int k = sphere_first_[r]; k < sphere_first_[r + 1]; ++k) {
            const Cx inv = inverse(Cx{target.positions[i].x() - x_[k], target.positions[i].y() - y_[k]});
            const Cx inv_sq = mul(inv, inv);
            for (int c = 0; c < 2; ++c) {
              const Cx s = mul(Cx{f_[c][0][k], f_[c][1][k]}, inv_sq);
              sum[2 * i + c].re += s.re;
              sum[2 * i + c].im += s.im;
            }
          }
        }
      }
    }
  }
  // conj(u) = K sum: u = (K re, -K im).
  const double K = dipole_strength_;
  for (int i = 0; i < n; ++i) {
    target_forces.driving_disturbance(2 * i) += K * sum[2 * i].re;
    target_forces.driving_disturbance(2 * i + 1) -= K * sum[2 * i].im;
    target_forces.velocity_disturbance(2 * i) += K * sum[2 * i + 1].re;
    target_forces.velocity_disturbance(2 * i + 1) -= K * sum[2 * i + 1].im;
  }
  return K * std::max(bound[0], bound[1]);
}

}  // namespace hsrod
