#pragma once
// How many threads a "use every core" setting starts.

namespace lpvlab {

// The cores this process may run on: its CPU affinity mask (what taskset, a container or a Slurm
// allocation gave it), not every core of the machine as std::thread::hardware_concurrency says.
int availableCores();

}  // namespace lpvlab
