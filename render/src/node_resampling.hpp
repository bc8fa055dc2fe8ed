// A flexible body's nodes' motions (translation, then small rotation)
// resampled at the evenly spaced stations the vertex shader bends a mesh
// by (scene_view.cpp): along a beam or a boom, over a panel.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfurl::render {

using NodeMotion = Eigen::Matrix<double, 6, 1>;

struct StationMotion {
  double at = 0;  // along the line
  NodeMotion u;
};

// At n stations evenly from `from` over `length`: linear between the
// given ones (in any order; those at one place, a section's nodes,
// averaged), held beyond the ends.
std::vector<NodeMotion> resample_along(std::vector<StationMotion> stations, double from, double length, int n);

struct ScatteredMotion {
  Eigen::Vector2d at;  // in the grid's plane
  NodeMotion u;
};

// On an n x n grid over the box from `from` of `size` (rows along its
// second axis): Shepard's weights 1 / d^2 fading to nothing at 2.5 node
// spacings, smooth and local.
std::vector<NodeMotion> resample_over(const std::vector<ScatteredMotion>& nodes, const Eigen::Vector2d& from,
                                      const Eigen::Vector2d& size, int n);

}  // namespace unfurl::render
