#include "framework/radiosity/solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_for.h>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

double sum3(const glm::dvec3& v) { return v.x + v.y + v.z; }

// The largest of n values under updates, in O(log n) each: shooting's choice of the next shooter
// among hundreds of thousands of sides (a scan per shot would cost more than the shot).
class MaxTree {
public:
  explicit MaxTree(const std::vector<double>& values) : leaves_(1) {
    while (leaves_ < values.size()) leaves_ *= 2;
    node_.assign(2 * leaves_, std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) node_[leaves_ + i] = values[i];
    for (std::size_t i = leaves_ - 1; i > 0; --i) node_[i] = std::max(node_[2 * i], node_[2 * i + 1]);
  }
  void set(std::size_t i, double value) {
    std::size_t k = leaves_ + i;
    node_[k] = value;
    for (k /= 2; k > 0; k /= 2) node_[k] = std::max(node_[2 * k], node_[2 * k + 1]);
  }
  std::size_t largest() const {
    std::size_t k = 1;
    while (k < leaves_) k = node_[2 * k] >= node_[2 * k + 1] ? 2 * k : 2 * k + 1;
    return k - leaves_;
  }

private:
  std::size_t leaves_;
  std::vector<double> node_;
};

// sum_i A_i |S_i + rho_i (F R)_i - R_i|, summed over RGB.
double residual(const RadiositySystem& s, const FormFactorRows& rows, const std::vector<glm::dvec3>& source,
                const std::vector<glm::dvec3>& r) {
  const std::vector<glm::dvec3> fr = gatherIrradiance(rows, r);
  double total = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i)
    total += s.area[i] * sum3(glm::abs(source[i] + s.albedo[i] * fr[i] - r[i]));
  return total;
}

RadiositySolution gather(const RadiositySystem& s, FormFactorRows& rows, const RowSupply& supply,
                         const SolverSettings& settings) {
  const std::size_t n = s.sides();
  std::vector<std::uint32_t> all(n);
  std::iota(all.begin(), all.end(), 0u);
  supply(all);
  RadiositySolution out;
  out.emitted = gatherIrradiance(rows, s.exitance, &out.rowEntriesRead);
  std::vector<glm::dvec3> source(n);  // R1 = rho (P + He): the first reflection
  double sourcePower = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    source[i] = s.albedo[i] * (s.lightIrradiance[i] + out.emitted[i]);
    sourcePower += s.area[i] * sum3(source[i]);
  }
  std::vector<glm::dvec3> r(n, glm::dvec3(0.0)), next(n);
  for (long it = 1; it <= settings.maxIterations; ++it) {
    if (settings.solver == RadiositySolver::Jacobi) {
      tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        glm::dvec3 h(0.0);
        for (const FormFactor& f : rows.row(i)) h += double(f.value) * r[f.side];
        next[i] = source[i] + s.albedo[i] * h;
      });
      r.swap(next);
    } else {  // Gauss-Seidel: in place, in side order
      for (std::size_t i = 0; i < n; ++i) {
        glm::dvec3 h(0.0);
        for (const FormFactor& f : rows.row(i)) h += double(f.value) * r[f.side];
        r[i] = source[i] + s.albedo[i] * h;
      }
    }
    out.rowEntriesRead += 2 * rows.entries();  // the sweep and the residual's product
    const double relative = sourcePower > 0.0 ? residual(s, rows, source, r) / sourcePower : 0.0;
    out.log.add(it, relative);
    out.iterations = it;
    out.finalRelative = relative;
    if (!(relative > settings.tolerance)) {
      out.converged = std::isfinite(relative);
      break;
    }
  }
  out.indirect = gatherIrradiance(rows, r, &out.rowEntriesRead);
  out.firstBounce = gatherIrradiance(rows, source, &out.rowEntriesRead);
  out.reflected = std::move(r);
  return out;
}

RadiositySolution shoot(const RadiositySystem& s, FormFactorRows& rows, const RowSupply& supply,
                        const SolverSettings& settings,
                        const std::function<void(const ShootingEnergy&)>& onShot) {
  const std::size_t n = s.sides();
  // Unshot radiosity by generation: emitted (0), reflected once (1), reflected more (2).
  std::vector<glm::dvec3> unshot0 = s.exitance, unshot1(n), unshot2(n, glm::dvec3(0.0));
  RadiositySolution out;
  out.reflected.resize(n);
  out.emitted.assign(n, glm::dvec3(0.0));
  out.firstBounce.assign(n, glm::dvec3(0.0));
  std::vector<glm::dvec3> later(n, glm::dvec3(0.0));  // irradiance from generation 2 and up
  ShootingEnergy& books = out.energy;
  std::vector<double> power(n);  // unshot power per side, W over RGB
  for (std::size_t i = 0; i < n; ++i) {
    unshot1[i] = s.albedo[i] * s.lightIrradiance[i];
    out.reflected[i] = unshot1[i];
    power[i] = s.area[i] * sum3(unshot0[i] + unshot1[i]);
    books.firstShot += power[i];
  }
  books.unshot = books.firstShot;
  MaxTree largest(power);
  for (long shot = 1; shot <= settings.maxIterations; ++shot) {
    if (!(books.unshot > settings.tolerance * books.firstShot)) {
      out.converged = true;
      break;
    }
    const std::size_t shooter = largest.largest();
    if (!(power[shooter] > 0.0)) {  // the books' running sum kept a rounding residue: all is shot
      out.converged = true;
      break;
    }
    if (!rows.has(shooter)) {
      // Rows for the sides most likely to shoot next, as many as the estimator makes at once.
      std::vector<std::uint32_t> order;
      for (std::size_t i = 0; i < n; ++i)
        if (power[i] > 0.0 && !rows.has(i)) order.push_back(std::uint32_t(i));
      const std::size_t count = std::min(order.size(), std::max<std::size_t>(settings.rowBatch, 1));
      std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(count), order.end(),
                        [&](std::uint32_t a, std::uint32_t b) { return power[a] > power[b]; });
      order.resize(count);
      supply(order);
      if (!rows.has(shooter)) throw Error("radiosity: the form-factor estimator left a shooter's row out");
    }
    const glm::dvec3 g0 = unshot0[shooter], g1 = unshot1[shooter], g2 = unshot2[shooter];
    const double shooterArea = s.area[shooter];
    const double shotPower = power[shooter];
    double received = 0.0;
    for (const FormFactor& f : rows.row(shooter)) {
      const std::size_t j = f.side;
      const double fji = double(f.value) * shooterArea / s.area[j];  // reciprocity
      const glm::dvec3 h0 = fji * g0, h1 = fji * g1, h2 = fji * g2, h = h0 + h1 + h2;
      out.emitted[j] += h0;
      out.firstBounce[j] += h1;
      later[j] += h2;
      const glm::dvec3 bounced = s.albedo[j] * h;
      unshot1[j] += s.albedo[j] * h0;
      unshot2[j] += s.albedo[j] * (h1 + h2);
      out.reflected[j] += bounced;
      const double arriving = s.area[j] * sum3(h);
      received += arriving;
      const double kept = s.area[j] * sum3(bounced);
      books.absorbed += arriving - kept;
      books.unshot += kept;
      power[j] += kept;
      largest.set(j, power[j]);
    }
    out.rowEntriesRead += rows.row(shooter).size();
    books.escaped += shotPower - received;
    books.unshot -= shotPower;
    unshot0[shooter] = unshot1[shooter] = unshot2[shooter] = glm::dvec3(0.0);
    power[shooter] = 0.0;
    largest.set(shooter, 0.0);
    out.iterations = shot;
    out.finalRelative = books.firstShot > 0.0 ? std::max(0.0, books.unshot) / books.firstShot : 0.0;
    out.log.add(shot, out.finalRelative);
    if (onShot) onShot(books);
  }
  if (!out.converged) out.converged = !(books.unshot > settings.tolerance * books.firstShot);
  out.indirect.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.indirect[i] = out.firstBounce[i] + later[i];
  return out;
}

}  // namespace

RadiositySystem radiositySystem(const PatchMesh& mesh) {
  RadiositySystem s;
  for (std::size_t i = 0; i < mesh.sides(); ++i) {
    const Patch& p = mesh.patches[i / 2];
    s.area.push_back(p.area);
    s.albedo.emplace_back(p.albedo);
    s.exitance.emplace_back(p.exitance);
  }
  s.lightIrradiance.assign(mesh.sides(), glm::dvec3(0.0));
  return s;
}

RadiositySolver radiositySolverFromName(const std::string& name) {
  if (name == "jacobi") return RadiositySolver::Jacobi;
  if (name == "gauss_seidel") return RadiositySolver::GaussSeidel;
  if (name == "shooting") return RadiositySolver::Shooting;
  throw Error("radiosity: unknown solver '" + name + "' (jacobi, gauss_seidel, shooting)");
}

std::string radiositySolverName(RadiositySolver solver) {
  switch (solver) {
    case RadiositySolver::Jacobi: return "jacobi";
    case RadiositySolver::GaussSeidel: return "gauss_seidel";
    case RadiositySolver::Shooting: return "shooting";
  }
  return "?";
}

std::vector<glm::dvec3> gatherIrradiance(const FormFactorRows& rows, const std::vector<glm::dvec3>& x,
                                         std::size_t* entriesRead) {
  std::vector<glm::dvec3> h(rows.sides());
  tbb::parallel_for(std::size_t(0), rows.sides(), [&](std::size_t i) {
    glm::dvec3 sum(0.0);
    for (const FormFactor& f : rows.row(i)) sum += double(f.value) * x[f.side];
    h[i] = sum;
  });
  if (entriesRead) *entriesRead += rows.entries();
  return h;
}

RadiositySolution solveRadiosity(const RadiositySystem& system, FormFactorRows& rows, const RowSupply& supply,
                                 const SolverSettings& settings,
                                 const std::function<void(const ShootingEnergy&)>& onShot) {
  if (rows.sides() != system.sides()) throw Error("radiosity: form-factor rows and system differ in size");
  return settings.solver == RadiositySolver::Shooting ? shoot(system, rows, supply, settings, onShot)
                                                      : gather(system, rows, supply, settings);
}

nlohmann::json convergenceJson(const ConvergenceLog& log, std::size_t maxEntries) {
  nlohmann::json iterations = nlohmann::json::array(), values = nlohmann::json::array();
  const std::size_t n = log.iteration.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + maxEntries - 1) / std::max<std::size_t>(maxEntries, 1));
  for (std::size_t i = 0; i < n; ++i)
    if (i % stride == 0 || i + 1 == n) iterations.push_back(log.iteration[i]), values.push_back(log.relative[i]);
  return {{"iteration", iterations}, {"relative", values}};
}

}  // namespace lpvlab
