// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_TENSOR_VOTING_H
#define CGAL_BODT_3_TENSOR_VOTING_H

#include <CGAL/BODT_3/Vertex_star.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace CGAL {
namespace BODT_3 {

/// Thresholds that turn the paper's "mu_0 >> mu_1 ~ mu_2" into numbers: the
/// eigenvalues mu_0 >= mu_1 >= mu_2 of M = sum_i S_i n_i n_i^T (eq. 11) are
/// compared relative to mu_0.
///  - mu_1 / mu_0 <  `edge_ratio`: a smooth surface point (Algorithm 2);
///  - mu_1 / mu_0 >= `edge_ratio` and mu_2 / mu_0 < `corner_ratio`: a point on a
///    feature edge, whose direction is e_2 (Algorithm 3);
///  - mu_2 / mu_0 >= `corner_ratio`: a corner, which does not move.
/// Where two flat sides of equal area meet at a dihedral angle theta, the normals
/// differ by phi = 180 - theta degrees and mu_1 / mu_0 = tan^2(phi / 2): the
/// default edge ratio 0.05 marks edges whose normals turn by more than about 25
/// degrees. The defaults come from the experiment of bench/tensor_voting_thresholds
/// (recorded in doc/manual.md): on the generated inputs they miss no sharp-edge
/// vertex and no corner, and constrain 1% of the smooth-surface vertices.
///
/// With `angle_weighted` (the default) each triangle votes with its angle at the
/// vertex instead of its area S_i: then the two flat sides of a straight edge
/// weigh pi each whatever their triangulation, and the ratio depends on the
/// dihedral angle alone; area weights let one side with slim triangles hide the
/// edge (see the measurements in doc/manual.md).
struct Tensor_voting_options
{
  double edge_ratio = 0.05;
  double corner_ratio = 0.05;
  bool angle_weighted = true;
};

enum class Voted_kind
{
  surface,
  feature,
  corner
};

template <class K>
struct Tensor_vote
{
  Voted_kind kind;
  typename K::Vector_3 direction;   // e_2, for a feature point
};

/// Classifies a boundary vertex from the boundary triangles of its star (eq. 11).
template <class K>
Tensor_vote<K> tensor_vote(const Vertex_star<K>& star, const Tensor_voting_options& th)
{
  using Vector = typename K::Vector_3;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for(const auto& f : star.boundary)
  {
    const Vector u = f.a - star.x0, v = f.b - star.x0;
    const Vector w = CGAL::cross_product(u, v);   // 2 S_i n_i
    const double len = std::sqrt(w.squared_length());
    if(!(len > 0)) continue;
    const Eigen::Vector3d n(w.x() / len, w.y() / len, w.z() / len);
    const double weight = th.angle_weighted ? std::atan2(len, u * v) : 0.5 * len;
    M += weight * n * n.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(M);   // eigenvalues in increasing order
  const Eigen::Vector3d mu = eig.eigenvalues();
  const double mu0 = mu[2], mu1 = mu[1], mu2 = mu[0];
  const Eigen::Vector3d e2 = eig.eigenvectors().col(0);
  Tensor_vote<K> vote{Voted_kind::surface, Vector(e2[0], e2[1], e2[2])};
  if(!(mu0 > 0)) return vote;
  if(mu2 >= th.corner_ratio * mu0) vote.kind = Voted_kind::corner;
  else if(mu1 >= th.edge_ratio * mu0) vote.kind = Voted_kind::feature;
  return vote;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_TENSOR_VOTING_H
