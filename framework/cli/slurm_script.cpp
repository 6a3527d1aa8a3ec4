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

// The #SBATCH lines and the environment every job of the sweep starts with.
std::string header(const std::string& jobName, const std::string& dir, const SlurmResources& r,
                   const std::string& output) {
  std::ostringstream s;
  s << "#SBATCH --job-name=" << jobName << "\n"
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

}  // namespace

void checkSlurmResources(const SlurmResources& r) {
  if (r.cpusPerTask < 1)
    throw Error("--cpus-per-task: " + std::to_string(r.cpusPerTask) + " is below 1");
  if (!std::regex_match(r.memory, std::regex("[0-9]+[KMGT]?")))
    throw Error("--mem: '" + r.memory + "' is not a size sbatch reads (e.g. 4G, 500M)");
  if (!std::regex_match(r.time, std::regex("([0-9]+-)?[0-9]+(:[0-9]{2}){0,2}")))
    throw Error("--time: '" + r.time +
                "' is not a time limit sbatch reads (e.g. 01:00:00, 2-00:00:00, 30)");
}

void writeSlurmScripts(const fs::path& dir, const std::string& lpvlab, const std::string& stem,
                       const std::vector<SweepConfiguration>& configurations,
                       const std::vector<std::string>& referenceKeys,
                       const SlurmResources& resources) {
  const std::string d = absolute(dir.string());
  fs::create_directories(dir / "logs");

  std::ostringstream array;
  array << "#!/bin/bash\n"
        << "# lpvlab sweep of " << stem << ": task i runs configuration i (unless complete).\n"
        << "# Submit: " << d << "/submit.sh   then: lpvlab summary " << d << "\n"
        << "#SBATCH --array=0-" << configurations.size() - 1 << "\n"
        << header(stem + "-sweep", d, resources, "%A_%a.out") << "DIR=" << shellQuoted(d) << "\n"
        << "LPVLAB=" << shellQuoted(lpvlab) << "\n"
        << "IDS=(";
  for (std::size_t i = 0; i < configurations.size(); ++i)
    array << (i ? " " : "") << configurations[i].id;
  array << ")\n"
        << "ID=${IDS[$SLURM_ARRAY_TASK_ID]}\n"
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
         << "# lpvlab sweep of " << stem << ": renders (or reuses) the " << renderers.size()
         << " reference(s) its configurations compare with, once, before the array runs.\n"
         << header(stem + "-references", d, resources, "%j_references.out")
         << "DIR=" << shellQuoted(d) << "\n"
         << "LPVLAB=" << shellQuoted(lpvlab) << "\n"
         << "for ID in";
    for (const std::string& id : renderers) refs << " " << id;
    refs << "; do\n"
         << "  \"$LPVLAB\" reference \"$DIR/configs/$ID.toml\"\n"
         << "done\n";
    writeTextAtomically((dir / "references.slurm").string(), refs.str());
  } else {
    fs::remove(dir / "references.slurm");
  }

  std::ostringstream submit;
  submit
      << "#!/bin/bash\n"
      << "# Submits the sweep of " << stem
      << (renderers.empty()
              ? ""
              : ": the references job, then the array, which starts once it succeeded")
      << ".\n"
      << "# Arguments are sbatch options for every job; they override the scripts' #SBATCH lines,\n"
      << "# e.g. " << d << "/submit.sh --partition=long --time=04:00:00\n"
      << "# Prints the array's job id last.\n"
      << "set -euo pipefail\n"
      << "DIR=" << shellQuoted(d) << "\n";
  if (renderers.empty()) {
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

}  // namespace lpvlab::cli
