// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_CLASSIFICATION_TENSOR_VOTING_H
#define CGAL_BODT_3_INTERNAL_CLASSIFICATION_TENSOR_VOTING_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/internal/Moves/Vertex_star.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace CGAL {
namespace BODT_3 {
namespace internal {

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

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_CLASSIFICATION_TENSOR_VOTING_H
