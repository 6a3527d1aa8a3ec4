#include "framework/gl/gpu_timer.h"

#include "framework/core/error.h"
#include "framework/gl/context.h"

namespace lpvlab {

GpuTimer::GpuTimer() = default;

GpuTimer::~GpuTimer() {
  for (const Pending& p : pending_) {
    glDeleteQueries(1, &p.start);
    if (p.stop) glDeleteQueries(1, &p.stop);
  }
  if (!freeQueries_.empty()) glDeleteQueries(GLsizei(freeQueries_.size()), freeQueries_.data());
}

GLuint GpuTimer::take() {
  if (freeQueries_.empty()) {
    GLuint query = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &query);
    return query;
  }
  const GLuint query = freeQueries_.back();
  freeQueries_.pop_back();
  return query;
}

void GpuTimer::stamp(GLuint query) {
  glQueryCounter(query, GL_TIMESTAMP);
  // llvmpipe writes a timestamp when it executes the queued commands, at the next flush, but runs
  // a compute dispatch at once: unflushed, both stamps of a dispatch are taken after it, a few
  // nanoseconds apart. A flush per stamp costs a GPU driver little.
  glFlush();
}

void GpuTimer::begin(const std::string& stage) {
  if (!GlContext::glLoaded()) return;  // no GL: nothing of a stage runs on it (its wall time counts)
  if (!pending_.empty() && !pending_.back().stop)
    throwAt("GPU timer", "stage '" + stage + "' begun inside '" + pending_.back().stage +
                             "' (stages may not nest)");
  pending_.push_back({stage, take(), 0});
  stamp(pending_.back().start);
}

void GpuTimer::end() {
  if (!GlContext::glLoaded()) return;
  if (pending_.empty() || pending_.back().stop) throwAt("GPU timer", "end() without begin()");
  pending_.back().stop = take();
  stamp(pending_.back().stop);
}

std::map<std::string, double> GpuTimer::collectMs() {
  if (!pending_.empty() && !pending_.back().stop)
    throwAt("GPU timer", "stage '" + pending_.back().stage + "' was not ended");
  std::map<std::string, double> ms;
  for (const Pending& p : pending_) {
    GLuint64 start = 0, stop = 0;
    glGetQueryObjectui64v(p.start, GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(p.stop, GL_QUERY_RESULT, &stop);
    ms[p.stage] += double(stop - start) * 1e-6;
    freeQueries_.push_back(p.start);
    freeQueries_.push_back(p.stop);
  }
  pending_.clear();
  return ms;
}

}  // namespace lpvlab
