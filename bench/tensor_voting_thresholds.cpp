// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The experiment behind the default tensor-voting thresholds. Mesh_3 knows which
// vertices lie on protected feature curves and corners; here that knowledge is
// hidden from the classifier, which must find features by tensor voting (eq. 11).
// For each pair of thresholds it reports, over the generated inputs:
//  - false features: smooth-surface vertices (Mesh_3 dimension 2) classified as
//    feature or corner (they would be needlessly constrained);
//  - missed features: feature-curve vertices (dimension 1) classified as surface
//    (they would leave their sharp edge);
//  - missed corners: corners (dimension 0) classified as movable.
#include "inputs/generated_inputs.h"

#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_view.h>

#include <cstdio>
#include <cstring>

using namespace bodt_inputs;
namespace BODT = CGAL::BODT_3;

int main(int argc, char** argv)
{
  const Size size = argc > 1 && !std::strcmp(argv[1], "--benchmark") ? Size::benchmark : Size::small;
  std::vector<Generated_mesh> inputs;
  for(Shape s : all_shapes()) inputs.push_back(make_input(s, size));

  std::printf("| weights | edge ratio | corner ratio | false features (of dim-2) | missed features (of dim-1) | missed corners (of dim-0) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for(bool angle_weighted : {false, true})
  for(double edge : {0.02, 0.05, 0.1, 0.2, 0.3})
    for(double corner : {0.05, 0.1, 0.2})
    {
      std::size_t surface = 0, false_features = 0, curve = 0, missed = 0, corners = 0, missed_corners = 0;
      for(auto& input : inputs)
      {
        BODT::internal::C3t3_adapter<C3t3> adapter(input.c3t3);
        BODT::internal::Flat_view<BODT::internal::C3t3_adapter<C3t3>> view(adapter);
        const BODT::internal::Feature_hints truth = BODT::internal::c3t3_feature_hints(input.c3t3, view);
        BODT::internal::Classification_options opt;
        opt.tensor_voting.edge_ratio = edge;
        opt.tensor_voting.corner_ratio = corner;
        opt.tensor_voting.angle_weighted = angle_weighted;
        // No hints, and no interfaces either (interfaces would count as patches):
        // classify the outer boundary of each input by tensor voting alone.
        auto& mesh = view.mesh();
        for(std::size_t c = 0; c < mesh.cells.size(); ++c)
          if(mesh.in_mesh[c]) mesh.subdomain[c] = 1;
        const auto classification = BODT::internal::classify_vertices(mesh, BODT::internal::Feature_hints(), opt);
        for(std::size_t v = 0; v < classification.kind.size(); ++v)
        {
          // Only the outer boundary: vertices with boundary facets.
          if(mesh.boundary_begin[v + 1] == mesh.boundary_begin[v]) continue;
          const int dim = truth.dimension[v];
          const BODT::internal::Vertex_kind k = classification.kind[v];
          if(dim == 2)
          {
            ++surface;
            if(k != BODT::internal::Vertex_kind::surface) ++false_features;
          }
          else if(dim == 1 && input.name != name(Shape::two_subdomains))
          {
            // (The junction circle of two_subdomains is no sharp feature of the ball.)
            ++curve;
            if(k == BODT::internal::Vertex_kind::surface) ++missed;
          }
          else if(dim == 0)
          {
            ++corners;
            if(k != BODT::internal::Vertex_kind::fixed) ++missed_corners;
          }
        }
      }
      std::printf("| %s | %g | %g | %zu of %zu (%.1f%%) | %zu of %zu (%.1f%%) | %zu of %zu |\n",
                  angle_weighted ? "angle" : "area (eq. 11)", edge, corner,
                  false_features, surface, 100.0 * false_features / surface, missed, curve,
                  100.0 * missed / curve, missed_corners, corners);
    }
  return 0;
}
