/**
 * @file timer.h
 * Wall-clock helper for the per-phase times of summary.json. Times never go
 * to standard output (the test oracle).
 */
#ifndef common_io_timer_h
#define common_io_timer_h

#include <chrono>

namespace Common
{
  namespace IO
  {
    /** @brief Seconds of wall time elapsed since @p start. */
    inline double
    seconds_since(const std::chrono::steady_clock::time_point &start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }
  } // namespace IO
} // namespace Common

#endif
