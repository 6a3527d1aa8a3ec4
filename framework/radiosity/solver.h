#pragma once
// The radiosity system (seed 004, equations 2-2 and 3-1/3-2) and its three solvers.
//
// Per side i (area A_i, albedo rho_i): E_i, its emitted exitance (pi L_e, W/m^2), and P_i, the
// irradiance straight from the punctual lights (light_irradiance.h). Its radiosity is
//   B_i = E_i + rho_i (P_i + H_i),  H_i = sum_j F_ij B_j  (irradiance from the other surfaces).
// The solvers work on the reflected part R = B - E and keep apart, for the display:
//   emitted     He_i = sum_j F_ij E_j     light arriving straight from emissive surfaces (direct)
//   indirect    Hi_i = sum_j F_ij R_j     light reflected at least once before (what `indirect` is)
//   first       H1_i = sum_j F_ij R1_j    with R1 = rho (P + He): reflected exactly once before
//                                         (`indirect1`, the one-bounce reference's counterpart)
// Solvers:
//   jacobi        R <- rho (P + He + F R), every side from the previous iterate
//   gauss_seidel  the same, each side using the values already updated in this sweep (the seed's
//                 choice, 3.4: "radiosity computed in an iteration used within the same iteration")
//   shooting      progressive refinement (seed 004, 2.2.3.1; Cohen et al. 1988): the side with
//                 the most unshot power shoots it to every side it sees, through its own row and
//                 reciprocity (F_ji = A_i F_ij / A_j): only shooters need form factors
// Convergence, logged per iteration (a gathering sweep, or a shot): gathering's residual
// sum_i A_i |rho_i (P_i + He_i + (F R)_i) - R_i| over the source power sum_i A_i rho_i (P_i + He_i);
// shooting's unshot power over the power of the first shot sum_i A_i (E_i + rho_i P_i) (powers
// summed over RGB). Each stops when that falls to `tolerance` or after `maxIterations`.
// Shooting keeps the books of that power at every shot: shot so far = absorbed + escaped
// (leaves through an open scene) + unshot, to double rounding (energy()).
//
// Gathering solves with the rows F_ij as estimated from each side; shooting with their
// reciprocals. With exact form factors both are the same system; with estimated ones they differ
// by the estimators' reciprocity error (docs/variants/radiosity.md measures it).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "framework/radiosity/form_factors.h"
#include "framework/radiosity/patches.h"

namespace lpvlab {

struct RadiositySystem {
  std::vector<double> area;              // per side, m^2
  std::vector<glm::dvec3> albedo;        // per side
  std::vector<glm::dvec3> exitance;      // E, W/m^2
  std::vector<glm::dvec3> lightIrradiance;  // P, W/m^2
  std::size_t sides() const { return area.size(); }
};

// The system of a patch mesh without punctual light (lightIrradiance zeros): per side its
// patch's area, albedo and exitance.
RadiositySystem radiositySystem(const PatchMesh& mesh);

enum class RadiositySolver { Jacobi, GaussSeidel, Shooting };
RadiositySolver radiositySolverFromName(const std::string& name);  // as the experiment names them
std::string radiositySolverName(RadiositySolver solver);

struct SolverSettings {
  RadiositySolver solver = RadiositySolver::GaussSeidel;
  double tolerance = 1e-4;   // relative residual or unshot power
  long maxIterations = 1000;  // gathering sweeps, or shots
  std::size_t rowBatch = 1;   // shooting: rows asked for at once (the estimator's batch), for the
                              // sides with the most unshot power
};

struct ConvergenceLog {
  std::vector<long> iteration;   // 1-based
  std::vector<double> relative;  // residual or unshot fraction after it
  void add(long i, double value) { iteration.push_back(i), relative.push_back(value); }
};

// Shooting's books, W summed over RGB.
struct ShootingEnergy {
  double firstShot = 0.0;  // sum A (E + rho P): what the solve distributes
  double absorbed = 0.0, escaped = 0.0, unshot = 0.0;
};

struct RadiositySolution {
  std::vector<glm::dvec3> reflected;        // R = B - E, W/m^2
  std::vector<glm::dvec3> emitted;          // He
  std::vector<glm::dvec3> indirect;         // Hi
  std::vector<glm::dvec3> firstBounce;      // H1
  ConvergenceLog log;
  long iterations = 0;
  bool converged = false;
  double finalRelative = 0.0;
  ShootingEnergy energy;                    // shooting only
  std::size_t rowEntriesRead = 0;           // form factors multiplied (the solve's work)
};

// Rows on demand: makes sure the given sides' rows are in `rows` (the estimator computes the
// missing ones, in batches). Gathering asks for every side at once; shooting for shooters.
using RowSupply = std::function<void(const std::vector<std::uint32_t>& sides)>;

// `onShot` (may be null) is called after every shot of shooting with its books (tests check
// conservation at every step).
RadiositySolution solveRadiosity(const RadiositySystem& system, FormFactorRows& rows, const RowSupply& supply,
                                 const SolverSettings& settings,
                                 const std::function<void(const ShootingEnergy&)>& onShot = nullptr);

// H_i = sum_j F_ij x_j for every side (rows of all sides must be present).
std::vector<glm::dvec3> gatherIrradiance(const FormFactorRows& rows, const std::vector<glm::dvec3>& x,
                                         std::size_t* entriesRead = nullptr);

// The log as JSON, at most `maxEntries` entries (every k-th, always the last).
nlohmann::json convergenceJson(const ConvergenceLog& log, std::size_t maxEntries = 500);

}  // namespace lpvlab
