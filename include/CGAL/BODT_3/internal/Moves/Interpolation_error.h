// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_INTERPOLATION_ERROR_H
#define CGAL_BODT_3_INTERNAL_MOVES_INTERPOLATION_ERROR_H

#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The L1 error (eq. 5) between f(x) = |x - x0|^2 and its piecewise-linear
/// interpolant over the star of x* = x0 + X, as a function of the move X:
///
///   Error(X) = X^T Q X + b . X + constant,
///
/// exact for every X perpendicular to the (B.1) normal, where the cubic terms
/// vanish (Appendix C) and |Omega_*| = |Omega_0| (Appendix B). Derivation, with
/// Y_i = y_i - x0, w_i = Y_i x Y_{i+1} (outward), L_tau = sum_j |x_{tau,j} - x0|^2,
/// and S_tau n_tau the area vector of the face opposite x0 pointing towards x0:
///
///   sum_tau |tau*| / 4 (|X|^2 + L_tau) = |Omega_0|/4 |X|^2 + 1/12 (sum_tau S_tau n_tau L_tau) . X + const,
///   int_{Omega_*} f = int_{Omega_0} f + 1/60 sum_i (X^T (Y_i + Y_{i+1}) w_i^T X
///                                                  + (|Y_i|^2 + |Y_{i+1}|^2 + Y_i.Y_{i+1}) w_i . X),
///
/// so Q = |Omega_0|/4 I - sym(P)/60 with P = sum_i (Y_i + Y_{i+1}) w_i^T, and
/// b = 1/12 sum_tau S_tau n_tau L_tau - 1/60 sum_i (|Y_i|^2 + |Y_{i+1}|^2 + Y_i.Y_{i+1}) w_i.
/// Algorithms 1 to 3 minimize this over R^3, a plane, or a line.
template <class K>
class Interpolation_error
{
public:
  using Vector = typename K::Vector_3;

  explicit Interpolation_error(const Vertex_star<K>& star)
  {
    const auto& x0 = star.x0;
    double g[3] = {0, 0, 0};
    for(const auto& t : star.cells)
    {
      const Vector a = t.a - x0, b = t.b - x0, c = t.c - x0;
      volume_ += CGAL::determinant(a, b, c) / 6.0;
      const double L = a.squared_length() + b.squared_length() + c.squared_length();
      // S_tau n_tau = -(b - a) x (c - a) / 2: the face normal towards x0.
      const Vector s_n = -0.5 * CGAL::cross_product(b - a, c - a);
      g[0] += s_n.x() * L;
      g[1] += s_n.y() * L;
      g[2] += s_n.z() * L;
    }
    for(int i = 0; i < 3; ++i)
    {
      b_[i] = g[i] / 12.0;
      for(int j = 0; j < 3; ++j) q_[i][j] = (i == j) ? volume_ / 4.0 : 0.0;
    }
    for(const auto& f : star.boundary)
    {
      const Vector yi = f.a - x0, yj = f.b - x0;
      const Vector w = CGAL::cross_product(yi, yj);
      const Vector s = yi + yj;
      const double sv[3] = {s.x(), s.y(), s.z()};
      const double wv[3] = {w.x(), w.y(), w.z()};
      const double r = yi.squared_length() + yj.squared_length() + yi * yj;
      for(int i = 0; i < 3; ++i)
      {
        b_[i] -= r * wv[i] / 60.0;
        for(int j = 0; j < 3; ++j) q_[i][j] -= (sv[i] * wv[j] + sv[j] * wv[i]) / 120.0;
      }
    }
  }

  /// |Omega_0|, the volume of the star.
  double volume() const { return volume_; }

  /// u^T Q v.
  double quadratic(const Vector& u, const Vector& v) const
  {
    const double uv[3] = {u.x(), u.y(), u.z()};
    const double vv[3] = {v.x(), v.y(), v.z()};
    double s = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j) s += uv[i] * q_[i][j] * vv[j];
    return s;
  }

  /// b . u.
  double linear(const Vector& u) const { return b_[0] * u.x() + b_[1] * u.y() + b_[2] * u.z(); }

  /// b itself.
  Vector linear_term() const { return Vector(b_[0], b_[1], b_[2]); }

  /// Error(X) minus its constant: X^T Q X + b . X.
  double operator()(const Vector& x) const { return quadratic(x, x) + linear(x); }

private:
  double volume_ = 0;
  double q_[3][3];
  double b_[3];
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_INTERPOLATION_ERROR_H
