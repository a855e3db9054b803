// The time offset fitted jointly with X and Z: time_offset.h (docs/streams.md).
#include "hecal/streams/time_offset.h"

#include <algorithm>
#include <cmath>

#include "hecal/geometry/se3.h"

namespace hecal::streams {
namespace {

struct Brent {
  double x = 0.0;
  double fx = 0.0;
  int evaluations = 0;
};

// Brent's minimisation of f on [a, b] to absolute tolerance tol (Brent 1973, ch. 5: golden
// section with parabolic steps).
template <typename F>
Brent Minimise(const F& f, double a, double b, double tol) {
  constexpr double kGolden = 0.3819660112501051;  // (3 − √5) / 2
  Brent out;
  double x = a + kGolden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  out.evaluations = 1;
  double d = 0.0, e = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double m = 0.5 * (a + b);
    const double tol1 = tol + 1e-10 * std::abs(x);
    const double tol2 = 2.0 * tol1;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;
    bool golden = true;
    if (std::abs(e) > tol1) {
      // A parabola through x, w, v.
      double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      if (std::abs(p) < std::abs(0.5 * q * e) && p > q * (a - x) && p < q * (b - x)) {
        e = d;
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < m ? tol1 : -tol1;
        golden = false;
      }
    }
    if (golden) {
      e = (x < m ? b : a) - x;
      d = kGolden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + (d > 0 ? tol1 : -tol1);
    const double fu = f(u);
    ++out.evaluations;
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  out.x = x;
  out.fx = fx;
  return out;
}

// (δX, δZ) of `p` relative to `at`, right perturbations.
Eigen::Matrix<double, 12, 1> Difference(const ProfilePoint& at, const ProfilePoint& p) {
  Eigen::Matrix<double, 12, 1> d;
  d.head<6>() = se3::Log(at.X.inverse() * p.X);
  d.tail<6>() = se3::Log(at.Z.inverse() * p.Z);
  return d;
}

}  // namespace

OffsetMinimum MinimiseProfile(const Profile& profile, double start, double low, double high,
                              double step, double tolerance) {
  OffsetMinimum out;
  double best = start;
  double best_cost = profile(start).cost;
  const int points = static_cast<int>(std::ceil((high - low) / step));
  for (int k = 0; k <= points; ++k) {
    const double offset = std::min(low + k * step, high);
    const double cost = profile(offset).cost;
    if (cost < best_cost) {
      best = offset;
      best_cost = cost;
    }
  }
  out.evaluations = points + 2;
  const Brent found = Minimise([&](double offset) { return profile(offset).cost; },
                               std::max(best - step, low), std::min(best + step, high), tolerance);
  out.evaluations += found.evaluations;
  out.offset = found.fx <= best_cost ? found.x : best;
  out.on_edge = out.offset - low < 4 * tolerance || high - out.offset < 4 * tolerance;
  return out;
}

OffsetUncertainty ProfileUncertainty(const Profile& profile, double offset, const ProfilePoint& at,
                                     double step) {
  OffsetUncertainty out;
  out.slope.setZero();
  out.added.setZero();
  double h = step;
  ProfilePoint plus, minus;
  double rise = 0.0;
  for (int round = 0; round < 4; ++round) {
    plus = profile(offset + h);
    minus = profile(offset - h);
    rise = 0.5 * (plus.cost + minus.cost) - at.cost;
    if (!(rise > 0)) break;
    if (rise > 1.0 && rise < 16.0) break;
    h *= std::clamp(std::sqrt(4.0 / rise), 0.1, 10.0);  // aim at a rise of about 4
  }
  if (!(rise > 0) || !std::isfinite(rise)) {
    out.curved = false;
    return out;
  }
  const double curvature = 2.0 * rise / (h * h);  // d²χ²/dδ²
  const double variance = 2.0 / curvature;
  out.sigma = std::sqrt(variance);
  out.slope = (Difference(at, plus) - Difference(at, minus)) / (2.0 * h);
  out.added = out.slope * variance * out.slope.transpose();
  return out;
}

}  // namespace hecal::streams
