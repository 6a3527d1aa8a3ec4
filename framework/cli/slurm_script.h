#pragma once
// `lpvlab sweep --emit slurm`: the batch scripts that run a sweep on a Slurm cluster.
//
//   DIR/sweep.slurm       a job array: task i runs configuration i unless it is complete
//   DIR/references.slurm  only when configurations compare with a reference: one job that renders
//                         (or reuses) each distinct reference once, before the array starts
//   DIR/submit.sh         submits both, the array depending on the references job; its
//                         arguments are sbatch options for both jobs (they override the
//                         #SBATCH lines)
//
// Each script states the resources a task asks for and the environment lpvlab reads
// (LPVLAB_SHARED_DIR, LPVLAB_CACHE_DIR), as resolved when the scripts were written, instead of
// relying on sbatch copying the submitting shell's environment.

#include <filesystem>
#include <string>
#include <vector>

#include "framework/experiment/sweep_expansion.h"

namespace lpvlab::cli {

struct SlurmResources {
  int cpusPerTask = 2;
  std::string memory = "4G";      // sbatch --mem: a number with an optional K, M, G or T suffix
  std::string time = "01:00:00";  // sbatch --time: [D-]HH:MM:SS, HH:MM:SS, MM:SS or minutes
};

// Throws an Error naming the option when a value is not one sbatch accepts.
void checkSlurmResources(const SlurmResources& resources);

// referenceKeys: per configuration, the key of the reference it compares with ("" for none).
void writeSlurmScripts(const std::filesystem::path& dir, const std::string& lpvlab,
                       const std::string& stem,
                       const std::vector<SweepConfiguration>& configurations,
                       const std::vector<std::string>& referenceKeys,
                       const SlurmResources& resources);

}  // namespace lpvlab::cli
