// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_FEATURE_ANGLES_H
#define BODT_CLI_FEATURE_ANGLES_H

// Angles for the tensor-voting thresholds, which the library takes as eigenvalue
// ratios of M = sum w_i n_i n_i^T (Tensor_voting.h): users think of a feature as
// an edge where the surface turns by more than some angle. The command line
// (--feature-angle, --corner-angle), the Python module (feature_angle,
// corner_angle) and the report's pictures use these functions and nothing else.
//
// With angle weights, each flat side around a vertex votes with its angle there,
// so for these model shapes the ratio depends on the angle alone:
//  - an edge where two flat sides meet with normals turning by phi:
//    mu_1 / mu_0 = tan^2(phi / 2);
//  - a corner where three flat sides meet symmetrically, each two normals apart by
//    psi (a cube corner: 90): the eigenvalues are 1 + 2 cos psi and 1 - cos psi
//    twice, so mu_2 / mu_0 = (1 - cos psi) / (1 + 2 cos psi) for psi <= 90.
// Both ratios reach 1 at 90 degrees, and no ratio of M exceeds 1, so the angles run
// over (0, 90]. Normals are votes without sign: an edge whose normals turn by phi
// above 90 degrees gives the ratio of 180 - phi, so with a feature angle A the
// edges found are those turning by between A and 180 - A (a blade thinner than A
// looks flat to tensor voting).

#include <cmath>

namespace bodt_cli {

inline constexpr double pi = 3.14159265358979323846;

/// The edge ratio (`feature_edge_ratio`) that marks edges turning by more than `degrees`.
inline double edge_ratio_of_angle(double degrees)
{
  const double t = std::tan(degrees * pi / 360);
  return t * t;
}

/// The turn, in degrees, that an edge ratio marks: 25.21 for the default 0.05.
inline double angle_of_edge_ratio(double ratio) { return 2 * std::atan(std::sqrt(ratio)) * 180 / pi; }

/// The corner ratio (`feature_corner_ratio`) that makes a symmetric three-sided
/// corner whose normals are `degrees` apart a corner.
inline double corner_ratio_of_angle(double degrees)
{
  const double c = std::cos(degrees * pi / 180);
  return (1 - c) / (1 + 2 * c);
}

/// The corner angle, in degrees, of a corner ratio: 30.27 for the default 0.05.
inline double angle_of_corner_ratio(double ratio) { return std::acos((1 - ratio) / (1 + 2 * ratio)) * 180 / pi; }

} // namespace bodt_cli

#endif // BODT_CLI_FEATURE_ANGLES_H
