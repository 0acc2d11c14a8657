// Timing of the renderer's passes (RenderResult::passes): GL_TIME_ELAPSED queries where the
// context has them, else glFinish around each pass and the wall clock between (TimingMethod).
#pragma once

#include <epoxy/gl.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "shadowvol/frame.h"
#include "shadowvol/gl/gl_error.h"
#include "shadowvol/gl/gl_objects.h"

namespace shadowvol::gl {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// Times passes: GL_TIME_ELAPSED queries (kept in a pool between frames) or glFinish + wall clock.
class PassTimer {
 public:
  PassTimer(std::vector<Query>& pool, bool gpu) : pool_(pool), gpu_(gpu) {}

  /// Appended to the names of the passes begun from now on ("#1": the scene's second light).
  void setSuffix(std::string suffix) { suffix_ = std::move(suffix); }

  void begin(const char* name) {
    entries_.push_back({name + suffix_, -1, 0.0});
    if (gpu_) {
      const std::size_t k = used_++;
      if (k >= pool_.size()) pool_.push_back(makeQuery());
      entries_.back().query = int(k);
      SV_GL(glBeginQuery(GL_TIME_ELAPSED, pool_[k].id()));
    } else {
      glFinish();
      t0_ = Clock::now();
    }
  }
  void end() {
    if (gpu_) {
      SV_GL(glEndQuery(GL_TIME_ELAPSED));
    } else {
      glFinish();
      entries_.back().ms = msSince(t0_);
    }
  }
  /// A CPU step measured by the caller (read-back, build, upload): always wall clock.
  void cpu(const char* name, double ms) { entries_.push_back({name + suffix_, -1, ms}); }

  std::vector<PassTime> results() {
    std::vector<PassTime> out;
    for (const auto& e : entries_) {
      double ms = e.ms;
      if (e.query >= 0) {
        GLuint64 ns = 0;
        SV_GL(glGetQueryObjectui64v(pool_[std::size_t(e.query)].id(), GL_QUERY_RESULT, &ns));
        ms = double(ns) * 1e-6;
      }
      out.push_back({e.name, ms});
    }
    return out;
  }

 private:
  struct Entry {
    std::string name;
    int query;
    double ms;
  };
  std::vector<Query>& pool_;
  bool gpu_;
  std::size_t used_ = 0;
  std::vector<Entry> entries_;
  Clock::time_point t0_;
  std::string suffix_;
};

/// RAII begin/end of one timed pass.
class TimedPass {
 public:
  TimedPass(PassTimer& t, const char* name) : t_(t) { t_.begin(name); }
  ~TimedPass() { t_.end(); }
  TimedPass(const TimedPass&) = delete;
  TimedPass& operator=(const TimedPass&) = delete;

 private:
  PassTimer& t_;
};

}  // namespace shadowvol::gl
