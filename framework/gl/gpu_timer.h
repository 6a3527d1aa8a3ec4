#pragma once
// GPU time of a stage from GL timestamp queries (glQueryCounter(GL_TIMESTAMP) before and after:
// llvmpipe's GL_TIME_ELAPSED gives meaningless values for compute dispatches, timestamps don't
// as long as each is flushed at once; see stamp()). Results are read back at the end of a frame
// so queries never stall the pipeline mid-frame. A stage timed twice in a frame adds up.

#include <map>
#include <string>
#include <vector>

#include <glad/gl.h>

namespace lpvlab {

class GpuTimer {
public:
  GpuTimer();
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin(const std::string& stage);   // stages may not nest
  void end();
  // Waits for all queries of this frame; returns stage -> milliseconds, then resets.
  std::map<std::string, double> collectMs();

private:
  struct Pending {
    std::string stage;
    GLuint start = 0, stop = 0;
  };
  std::vector<Pending> pending_;
  std::vector<GLuint> freeQueries_;
  GLuint take();
  void stamp(GLuint query);
};

}  // namespace lpvlab
