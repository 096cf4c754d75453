#ifndef tribos_base_timing_h
#define tribos_base_timing_h

#include <chrono>

namespace tribos
{
  /** Wall-clock seconds from @p start to now (a lap of this process's own
   * work, where TimerOutput's sections would include waits for others). */
  inline double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }
} // namespace tribos

#endif
