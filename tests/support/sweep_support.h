#pragma once
// A sweep directory's sweep.json naming the given configuration ids, for tests that write run
// manifests by hand and summarise them: writeSweepSummary reads only the configurations that a
// sweep.json records.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lpvlab::test {

inline void writeSweepIndex(const std::filesystem::path& dir, const std::vector<std::string>& ids) {
  nlohmann::json index = {{"swept_keys", nlohmann::json::array()},
                          {"configurations", nlohmann::json::array()}};
  for (const std::string& id : ids) index["configurations"].push_back({{"id", id}, {"name", id}});
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "sweep.json") << index.dump(2) << "\n";
}

}  // namespace lpvlab::test
