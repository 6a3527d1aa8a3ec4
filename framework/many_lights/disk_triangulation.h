#pragma once
// The Delaunay triangulation of points in the unit disk, for incremental instant radiosity's VPL
// bookkeeping in a light's projection (seed 001, 3.2): where VPLs are densest (the shortest edges
// of the triangulation, 3.2.1) and where coverage is poorest (the point of the disk farthest from
// every VPL, a vertex of the Voronoi diagram or a point on the disk's rim, 3.2.2). CGAL's
// Delaunay_triangulation_2 does the geometry (exact predicates); this wrapper keeps CGAL out of
// every other translation unit.

#include <cstddef>
#include <memory>
#include <utility>

#include <glm/glm.hpp>

namespace lpvlab {

class DiskTriangulation {
public:
  DiskTriangulation();
  ~DiskTriangulation();
  DiskTriangulation(DiskTriangulation&&) noexcept;
  DiskTriangulation& operator=(DiskTriangulation&&) noexcept;

  void clear();
  // Adds point p (|p| <= 1) named `id`; ids must be unique, and so must points (an Error
  // otherwise).
  void insert(const glm::dvec2& p, int id);
  void remove(int id);
  std::size_t size() const;

  // The id to remove where points are densest: of the two ends of the shortest edge, the one whose
  // edges are shorter on average; with the shortest edge's length. {-1, inf} with fewer than two
  // points.
  std::pair<int, double> densest() const;
  // The point of the unit disk farthest from every point, and that distance: the largest empty
  // circle centred in the disk. Candidates are the Voronoi vertices inside the disk (the
  // circumcentres of the Delaunay triangles) and `rimSamples` points evenly spaced on the rim (a
  // circle's largest empty circles that touch the rim lie where Voronoi edges cross it: the
  // samples find them to within pi / rimSamples of arc, and so of radius). The centre with no
  // points.
  std::pair<glm::dvec2, double> largestEmptyCircle(int rimSamples = 256) const;
  // The id of the point nearest to p, the smallest id of those equally near (-1 with no points).
  int nearest(const glm::dvec2& p) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lpvlab
