#include "framework/cli/slurm_script.h"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/core/atomic_file.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string absolute(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

// The #SBATCH lines and the environment every job of the sweep starts with; `extra`: more
// #SBATCH lines (the array, --exclusive, --gres).
std::string header(const std::string& jobName, const std::string& dir, const SlurmResources& r,
                   const std::string& output, const std::string& extra) {
  std::ostringstream s;
  s << extra
    << "#SBATCH --job-name=" << jobName << "\n"
    << "#SBATCH --cpus-per-task=" << r.cpusPerTask << "\n"
    << "#SBATCH --mem=" << r.memory << "\n"
    << "#SBATCH --time=" << r.time << "\n"
    << "#SBATCH --output=" << dir << "/logs/" << output << "\n"
    << "set -euo pipefail\n"
    << "# What lpvlab reads from the environment, as resolved when this script was written:\n"
    << "export LPVLAB_SHARED_DIR=" << shellQuoted(absolute(sharedDirectory())) << "\n"
    << "export LPVLAB_CACHE_DIR=" << shellQuoted(absolute(defaultCacheDir())) << "\n";
  return s.str();
}

// "#SBATCH --array=0-N[%T]" for `tasks` tasks, at most `throttle` at once (0: no cap).
std::string arrayLine(std::size_t tasks, int throttle) {
  return "#SBATCH --array=0-" + std::to_string(tasks - 1) +
         (throttle > 0 ? "%" + std::to_string(throttle) : "") + "\n";
}

// A bash array of `ids`, and the one of this task.
std::string taskIds(const std::vector<std::string>& ids) {
  std::string line = "IDS=(";
  for (std::size_t i = 0; i < ids.size(); ++i) line += (i ? " " : "") + ids[i];
  return line + ")\nID=${IDS[$SLURM_ARRAY_TASK_ID]}\n";
}

// DIR/submit.sh: the references' array (when there are references), then the sweep's.
void writeSubmitScript(const fs::path& dir, const std::string& d, const std::string& stem,
                       bool references) {
  std::ostringstream submit;
  submit
      << "#!/bin/bash\n"
      << "# Submits the sweep of " << stem
      << (references ? ": the references' array, then the sweep's, which starts once every "
                       "reference succeeded"
                     : "")
      << ".\n"
      << "# Arguments are sbatch options for every job; they override the scripts' #SBATCH lines,\n"
      << "# e.g. " << d << "/submit.sh --partition=long --time=04:00:00\n"
      << "# Prints the array's job id last.\n"
      << "set -euo pipefail\n"
      << "DIR=" << shellQuoted(d) << "\n";
  if (!references) {
    submit << "sbatch --parsable \"$@\" \"$DIR/sweep.slurm\"\n";
  } else {
    submit << "REFERENCES=$(sbatch --parsable \"$@\" \"$DIR/references.slurm\")\n"
           << "echo \"references job: ${REFERENCES%%;*}\" >&2\n"
           << "sbatch --parsable --dependency=afterok:${REFERENCES%%;*} --kill-on-invalid-dep=yes "
              "\"$@\" \"$DIR/sweep.slurm\"\n";
  }
  writeTextAtomically((dir / "submit.sh").string(), submit.str());
  fs::permissions(dir / "submit.sh",
                  fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
}

}  // namespace

void checkSlurmResources(const SlurmResources& r, const std::string& prefix) {
  if (r.cpusPerTask < 1)
    throw Error(prefix + "cpus-per-task: " + std::to_string(r.cpusPerTask) + " is below 1");
  if (!std::regex_match(r.memory, std::regex("[0-9]+[KMGT]?")))
    throw Error(prefix + "mem: '" + r.memory + "' is not a size sbatch reads (e.g. 4G, 500M)");
  if (!std::regex_match(r.time, std::regex("([0-9]+-)?[0-9]+(:[0-9]{2}){0,2}")))
    throw Error(prefix + "time: '" + r.time +
                "' is not a time limit sbatch reads (e.g. 01:00:00, 2-00:00:00, 30)");
}

void checkSlurmOptions(const SlurmOptions& o) {
  checkSlurmResources(o.tasks, "--");
  checkSlurmResources(o.references, "--ref-");
  // TYPE[:MODEL]:COUNT or TYPE:COUNT, as sbatch --gres reads one resource (e.g. gpu:1, gpu:a100:2).
  if (!o.gres.empty() && !std::regex_match(o.gres, std::regex("[A-Za-z0-9_]+(:[A-Za-z0-9_.-]+)?:[0-9]+")))
    throw Error("--gres: '" + o.gres + "' is not a generic resource sbatch reads (e.g. gpu:1, gpu:a100:2)");
  if (o.throttle < 0)
    throw Error("--array-throttle: " + std::to_string(o.throttle) + " is below 0 (0: no cap)");
}

void writeSlurmScripts(const fs::path& dir, const std::string& lpvlab, const std::string& stem,
                       const std::vector<SweepConfiguration>& configurations,
                       const std::vector<std::string>& referenceKeys, const SlurmOptions& options) {
  const std::string d = absolute(dir.string());
  fs::create_directories(dir / "logs");
  std::vector<std::string> ids;
  for (const SweepConfiguration& c : configurations) ids.push_back(c.id);
  std::string sweepLines = arrayLine(ids.size(), options.throttle);
  if (options.exclusive) sweepLines += "#SBATCH --exclusive\n";
  if (!options.gres.empty()) sweepLines += "#SBATCH --gres=" + options.gres + "\n";

  std::ostringstream array;
  array << "#!/bin/bash\n"
        << "# lpvlab sweep of " << stem << ": task i runs configuration i (unless complete).\n"
        << "# Submit: " << d << "/submit.sh   then: lpvlab summary " << d << "\n"
        << (options.exclusive ? "# --exclusive: each task on nodes of its own, so no other job's load is in its timings.\n"
                              : "# Tasks may share a node: for timing sweeps emit with --exclusive.\n")
        << header(stem + "-sweep", d, options.tasks, "%A_%a.out", sweepLines)
        << "DIR=" << shellQuoted(d) << "\n"
        << "LPVLAB=" << shellQuoted(lpvlab) << "\n"
        << taskIds(ids)
        << "if [ -f \"$DIR/$ID/manifest.json\" ]; then echo \"$ID complete, skipped\"; exit 0; fi\n"
        << "rm -rf \"$DIR/$ID\"\n"
        << "echo \"$ID: lpvlab run on $(hostname)\"\n"
        << "exec \"$LPVLAB\" run \"$DIR/configs/$ID.toml\" --out \"$DIR/$ID\"\n";
  writeTextAtomically((dir / "sweep.slurm").string(), array.str());

  // One configuration per distinct reference renders it; the others' runs then reuse it.
  std::vector<std::string> renderers;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < configurations.size(); ++i)
    if (!referenceKeys[i].empty() && seen.insert(referenceKeys[i]).second)
      renderers.push_back(configurations[i].id);
  if (!renderers.empty()) {
    std::ostringstream refs;
    refs << "#!/bin/bash\n"
         << "# lpvlab sweep of " << stem << ": task j renders (or reuses, at once, when the cache "
         << "has it) the j-th of the " << renderers.size()
         << " reference(s) its configurations compare with, before the sweep's array runs.\n"
         << header(stem + "-references", d, options.references, "%A_%a_references.out",
                   arrayLine(renderers.size(), options.throttle))
         << "DIR=" << shellQuoted(d) << "\n"
         << "LPVLAB=" << shellQuoted(lpvlab) << "\n"
         << taskIds(renderers)
         << "exec \"$LPVLAB\" reference \"$DIR/configs/$ID.toml\"\n";
    writeTextAtomically((dir / "references.slurm").string(), refs.str());
  } else {
    fs::remove(dir / "references.slurm");
  }
  writeSubmitScript(dir, d, stem, !renderers.empty());
}

}  // namespace lpvlab::cli
