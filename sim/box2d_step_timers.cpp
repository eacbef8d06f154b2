// b2Timer's members as Box2D 2.4 writes them for Linux, run only when the timers are on.
#include "sim/box2d_step_timers.h"

#include <box2d/b2_timer.h>
#include <sys/time.h>

#include <atomic>

namespace plantsim::sim {
namespace {

std::atomic<bool> g_timers_on{false};

}  // namespace

void set_box2d_step_timers(bool on) { g_timers_on.store(on, std::memory_order_relaxed); }

bool box2d_step_timers() { return g_timers_on.load(std::memory_order_relaxed); }

}  // namespace plantsim::sim

b2Timer::b2Timer() { Reset(); }

void b2Timer::Reset() {
  if (!plantsim::sim::box2d_step_timers()) {
    m_start_sec = m_start_usec = 0;
    return;
  }
  timeval t;
  gettimeofday(&t, nullptr);
  m_start_sec = static_cast<unsigned long long>(t.tv_sec);
  m_start_usec = static_cast<unsigned long long>(t.tv_usec);
}

float b2Timer::GetMilliseconds() const {
  if (!plantsim::sim::box2d_step_timers()) return 0.0f;
  timeval t;
  gettimeofday(&t, nullptr);
  const auto start_sec = static_cast<time_t>(m_start_sec);
  const auto start_usec = static_cast<suseconds_t>(m_start_usec);
  return 1000.0f * static_cast<float>(t.tv_sec - start_sec) +
         0.001f * static_cast<float>(t.tv_usec - start_usec);
}
