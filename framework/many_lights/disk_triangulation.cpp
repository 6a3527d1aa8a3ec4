#include "framework/many_lights/disk_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Point = Kernel::Point_2;

double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

}  // namespace

struct DiskTriangulation::Impl {
  Delaunay triangulation;
  std::map<int, Delaunay::Vertex_handle> vertices;

  // Mean length of the edges at v.
  double meanEdge(Delaunay::Vertex_handle v) const {
    double sum = 0.0;
    int count = 0;
    auto around = triangulation.incident_vertices(v), done = around;
    if (around == nullptr) return 0.0;
    do {
      if (!triangulation.is_infinite(around)) sum += distance(v->point(), around->point()), ++count;
    } while (++around != done);
    return count ? sum / count : 0.0;
  }
};

DiskTriangulation::DiskTriangulation() : impl_(std::make_unique<Impl>()) {}
DiskTriangulation::~DiskTriangulation() = default;
DiskTriangulation::DiskTriangulation(DiskTriangulation&&) noexcept = default;
DiskTriangulation& DiskTriangulation::operator=(DiskTriangulation&&) noexcept = default;

void DiskTriangulation::clear() {
  impl_->triangulation.clear();
  impl_->vertices.clear();
}

void DiskTriangulation::insert(const glm::dvec2& p, int id) {
  if (impl_->vertices.count(id)) throw Error("disk triangulation: id " + std::to_string(id) + " is taken");
  const std::size_t before = impl_->triangulation.number_of_vertices();
  const Delaunay::Vertex_handle v = impl_->triangulation.insert(Point(p.x, p.y));
  if (impl_->triangulation.number_of_vertices() == before)  // CGAL returns the point already there
    throw Error("disk triangulation: id " + std::to_string(id) + " lies on id " +
                std::to_string(v->info()));
  v->info() = id;
  impl_->vertices[id] = v;
}

void DiskTriangulation::remove(int id) {
  const auto found = impl_->vertices.find(id);
  if (found == impl_->vertices.end()) return;
  impl_->triangulation.remove(found->second);
  impl_->vertices.erase(found);
}

std::size_t DiskTriangulation::size() const { return impl_->vertices.size(); }

std::pair<int, double> DiskTriangulation::densest() const {
  const Delaunay& t = impl_->triangulation;
  double shortest = std::numeric_limits<double>::infinity();
  Delaunay::Vertex_handle a, b;
  for (auto edge = t.finite_edges_begin(); edge != t.finite_edges_end(); ++edge) {
    const auto u = edge->first->vertex(t.cw(edge->second));
    const auto w = edge->first->vertex(t.ccw(edge->second));
    const double length = distance(u->point(), w->point());
    if (length < shortest) shortest = length, a = u, b = w;
  }
  if (!std::isfinite(shortest)) return {-1, shortest};
  return {impl_->meanEdge(a) <= impl_->meanEdge(b) ? a->info() : b->info(), shortest};
}

std::pair<glm::dvec2, double> DiskTriangulation::largestEmptyCircle(int rimSamples) const {
  const Delaunay& t = impl_->triangulation;
  if (t.number_of_vertices() == 0) return {glm::dvec2(0.0), 2.0};
  glm::dvec2 best(0.0);
  double bestDistance = -1.0;
  const auto consider = [&](const Point& p) {
    const double d = distance(p, t.nearest_vertex(p)->point());
    if (d > bestDistance) bestDistance = d, best = glm::dvec2(p.x(), p.y());
  };
  for (auto face = t.finite_faces_begin(); face != t.finite_faces_end(); ++face) {
    const Point c = t.circumcenter(face);
    if (c.x() * c.x() + c.y() * c.y() <= 1.0) consider(c);
  }
  for (int i = 0; i < rimSamples; ++i) {
    const double angle = 2.0 * M_PI * (i + 0.5) / rimSamples;
    consider(Point(std::cos(angle), std::sin(angle)));
  }
  consider(Point(0.0, 0.0));
  return {best, bestDistance};
}

int DiskTriangulation::nearest(const glm::dvec2& p) const {
  const Delaunay& t = impl_->triangulation;
  if (t.number_of_vertices() == 0) return -1;
  const Point q(p.x, p.y);
  const Delaunay::Vertex_handle v = t.nearest_vertex(q);
  // Points as near as the one CGAL found are among its Delaunay neighbours: of them the smallest
  // id, so that the answer does not depend on the order the points were inserted in.
  const double d = CGAL::squared_distance(q, v->point());
  int best = v->info();
  if (t.number_of_vertices() > 1) {
    auto around = t.incident_vertices(v), done = around;
    do {
      if (!t.is_infinite(around) && CGAL::squared_distance(q, around->point()) == d)
        best = std::min(best, around->info());
    } while (++around != done);
  }
  return best;
}

}  // namespace lpvlab
