// The radiosity solvers: the furnace (a closed box of albedo rho and uniform exitance E has
// B = E / (1 - rho) everywhere), Jacobi, Gauss-Seidel and shooting on one reciprocal system, the
// books of shooting at every shot, and the extremes.
#include <cmath>
#include <map>
#include <numeric>

#include <gtest/gtest.h>

#include "framework/radiosity/light_irradiance.h"
#include "framework/radiosity/ray_form_factors.h"
#include "framework/radiosity/solver.h"
#include "framework/reference/material_sampling.h"
#include "radiosity_scenes.h"

namespace lpvlab {
namespace {

struct Problem {
  Scene scene;
  PatchMesh mesh;
  RadiositySystem system;
  FormFactorRows rows;
};

// Every side's row by rays.
Problem problem(Scene scene, float patchSize, int rays) {
  Problem out{std::move(scene), {}, {}, {}};
  out.mesh = meshPatches(out.scene, patchSize, 100000);
  out.system = radiositySystem(out.mesh);
  out.rows = FormFactorRows(out.mesh.sides());
  const PatchRayScene rayScene(out.scene, out.mesh);
  std::vector<std::uint32_t> all(out.mesh.sides());
  std::iota(all.begin(), all.end(), 0u);
  RayFormFactors(out.mesh, rayScene, rays, 11).computeRows(all, out.rows);
  if (!out.scene.lights.empty())
    out.system.lightIrradiance =
        lightIrradiance(out.mesh, rayScene, LightSampler(out.scene, prepareMaterials(out.scene)).punctual(), 16).perSide;
  return out;
}

// Makes the rows reciprocal: A_i F_ij and A_j F_ji both become their mean. With exact form
// factors that changes nothing; estimated ones only become a consistent system.
void makeReciprocal(FormFactorRows& rows, const std::vector<double>& area) {
  const std::size_t n = rows.sides();
  std::vector<std::map<std::uint32_t, double>> exchange(n);  // A_i F_ij summed from both ends
  for (std::size_t i = 0; i < n; ++i)
    for (const FormFactor& f : rows.row(i)) {
      exchange[i][f.side] += 0.5 * area[i] * f.value;
      exchange[f.side][std::uint32_t(i)] += 0.5 * area[i] * f.value;
    }
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<FormFactor> row;
    for (const auto& [j, g] : exchange[i]) row.push_back({j, float(g / area[i])});
    rows.set(i, std::move(row));
  }
}

const RowSupply kHaveAll = [](const std::vector<std::uint32_t>&) {};

TEST(RadiositySolver, FurnaceConvergesToEOverOneMinusRhoForBothGatheringSolvers) {
  const glm::vec3 e(1.0f, 2.0f, 0.5f);
  for (float rho : {0.3f, 0.8f, 0.95f}) {
    Problem p = problem(test::closedCube(glm::vec3(rho), e), 0.34f, 64);
    std::map<RadiositySolver, long> sweeps;
    for (RadiositySolver solver : {RadiositySolver::Jacobi, RadiositySolver::GaussSeidel}) {
      const RadiositySolution s = solveRadiosity(p.system, p.rows, kHaveAll, {solver, 1e-10, 100000});
      ASSERT_TRUE(s.converged) << radiositySolverName(solver) << " rho " << rho;
      const glm::dvec3 expected = double(M_PI) * glm::dvec3(e) / (1.0 - rho);
      for (std::size_t i = 0; i < p.mesh.sides(); i += 2) {  // the inner sides
        const glm::dvec3 b = p.system.exitance[i] + s.reflected[i];
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], expected[c], 1e-7 * expected[c]) << i;
      }
      sweeps[solver] = s.iterations;
    }
    // Gauss-Seidel needs fewer sweeps than Jacobi (the seed's finding, 3.4).
    EXPECT_LT(sweeps[RadiositySolver::GaussSeidel], sweeps[RadiositySolver::Jacobi]) << rho;
  }
}

TEST(RadiositySolver, FurnaceHoldsForShootingOnReciprocalFormFactors) {
  const glm::vec3 e(1.0f);
  const float rho = 0.7f;
  Problem p = problem(test::closedCube(glm::vec3(rho), e), 0.34f, 64);
  // Equal patches of a cube: symmetrising keeps the rows of the inner sides summing to 1 only
  // in expectation, so test the exact furnace on a system that is both closed and reciprocal:
  // every inner side sees every other equally.
  const std::size_t inner = p.mesh.patches.size();
  for (std::size_t i = 0; i < inner; ++i) {
    std::vector<FormFactor> row;
    for (std::size_t j = 0; j < inner; ++j)
      if (j != i) row.push_back({std::uint32_t(2 * j), float(1.0 / double(inner - 1))});
    p.rows.set(2 * i, std::move(row));
    p.rows.set(2 * i + 1, {});
  }
  const RadiositySolution s = solveRadiosity(p.system, p.rows, kHaveAll, {RadiositySolver::Shooting, 1e-10, 10000000});
  ASSERT_TRUE(s.converged);
  const double expected = M_PI / (1.0 - rho);
  for (std::size_t i = 0; i < p.mesh.sides(); i += 2)
    EXPECT_NEAR(p.system.exitance[i].x + s.reflected[i].x, expected, 1e-6 * expected);
}

TEST(RadiositySolver, JacobiGaussSeidelAndShootingReachTheSameSolution) {
  // An open box (no front wall), walls of two colours, emissive back wall, a point light.
  Scene scene = test::closedCube(glm::vec3(0.6f, 0.5f, 0.4f), glm::vec3(0.0f));
  scene.meshes.pop_back();  // the front: light escapes through it
  scene.materials.push_back(test::plainMaterial("glow", glm::vec3(0.3f), glm::vec3(0.5f, 0.4f, 0.2f)));
  scene.meshes[4].material = 1;  // the back wall emits
  Light bulb;
  bulb.position = glm::vec3(0.3f, 0.8f, 0.6f);
  bulb.intensity = 3.0f;
  scene.lights.push_back(bulb);
  Problem p = problem(scene, 0.25f, 256);
  makeReciprocal(p.rows, p.system.area);
  std::vector<RadiositySolution> solutions;
  for (RadiositySolver solver : {RadiositySolver::Jacobi, RadiositySolver::GaussSeidel, RadiositySolver::Shooting}) {
    solutions.push_back(solveRadiosity(p.system, p.rows, kHaveAll, {solver, 1e-11, 10000000}));
    ASSERT_TRUE(solutions.back().converged) << radiositySolverName(solver);
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < p.mesh.sides(); ++i) largest = std::max(largest, solutions[0].indirect[i].x);
  ASSERT_GT(largest, 0.0);
  for (std::size_t k = 1; k < 3; ++k)
    for (std::size_t i = 0; i < p.mesh.sides(); ++i) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(solutions[k].reflected[i][c], solutions[0].reflected[i][c], 1e-7 * largest) << k << " " << i;
        EXPECT_NEAR(solutions[k].indirect[i][c], solutions[0].indirect[i][c], 1e-7 * largest) << k << " " << i;
        EXPECT_NEAR(solutions[k].emitted[i][c], solutions[0].emitted[i][c], 1e-7 * largest) << k << " " << i;
        EXPECT_NEAR(solutions[k].firstBounce[i][c], solutions[0].firstBounce[i][c], 1e-7 * largest) << k << " " << i;
      }
    }
}

TEST(RadiositySolver, ShootingKeepsItsBooksAtEveryShot) {
  Scene scene = test::closedCube(glm::vec3(0.7f), glm::vec3(0.0f));
  scene.meshes.pop_back();
  Light bulb;
  bulb.position = glm::vec3(0.5f, 0.9f, 0.5f);
  scene.lights.push_back(bulb);
  Problem p = problem(scene, 0.25f, 128);  // not reciprocal: the books hold all the same
  long shots = 0;
  double previousUnshot = std::numeric_limits<double>::infinity();
  const RadiositySolution s = solveRadiosity(
      p.system, p.rows, kHaveAll, {RadiositySolver::Shooting, 1e-6, 10000000}, [&](const ShootingEnergy& books) {
        ++shots;
        EXPECT_NEAR(books.absorbed + books.escaped + books.unshot, books.firstShot, 1e-12 * books.firstShot);
        EXPECT_GE(books.absorbed, 0.0);
        EXPECT_GE(books.escaped, 0.0);
        EXPECT_LE(books.unshot, previousUnshot * (1.0 + 1e-12));
        previousUnshot = books.unshot;
      });
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(shots, s.iterations);
  EXPECT_GT(s.energy.escaped, 0.0);  // through the open side
  EXPECT_GT(s.energy.firstShot, 0.0);
}

TEST(RadiositySolver, ExtremesStayFinite) {
  // No light at all: zeros, converged at once.
  Problem dark = problem(test::closedCube(glm::vec3(0.5f), glm::vec3(0.0f)), 0.5f, 32);
  for (RadiositySolver solver : {RadiositySolver::Jacobi, RadiositySolver::GaussSeidel, RadiositySolver::Shooting}) {
    const RadiositySolution s = solveRadiosity(dark.system, dark.rows, kHaveAll, {solver, 1e-4, 1000});
    EXPECT_TRUE(s.converged);
    for (const glm::dvec3& r : s.indirect) EXPECT_EQ(r, glm::dvec3(0.0));
  }
  // Albedo 1 in a closed box: no solution exists; the solvers stop at their limit, unconverged,
  // finite, and say so.
  Problem white = problem(test::closedCube(glm::vec3(1.0f), glm::vec3(1e30f)), 0.5f, 32);
  for (RadiositySolver solver : {RadiositySolver::Jacobi, RadiositySolver::GaussSeidel, RadiositySolver::Shooting}) {
    const RadiositySolution s = solveRadiosity(white.system, white.rows, kHaveAll, {solver, 1e-4, 200});
    EXPECT_FALSE(s.converged) << radiositySolverName(solver);
    EXPECT_EQ(s.iterations, 200);
    for (const glm::dvec3& r : s.reflected) EXPECT_TRUE(std::isfinite(r.x + r.y + r.z));
  }
  // Zero iterations: nothing solved, nothing invented.
  const RadiositySolution none = solveRadiosity(dark.system, dark.rows, kHaveAll, {RadiositySolver::GaussSeidel, 1e-4, 0});
  EXPECT_EQ(none.iterations, 0);
  EXPECT_FALSE(none.converged);
}

}  // namespace
}  // namespace lpvlab
