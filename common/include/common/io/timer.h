/**
 * @file timer.h
 * Wall-clock and processor-time helpers for the per-phase times of
 * summary.json. Times never go
 * to standard output (the test oracle).
 */
#ifndef common_io_timer_h
#define common_io_timer_h

#include <chrono>
#include <ctime>

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

    /** @brief Processor time of this process so far (s): unlike wall
     * time, it does not grow while other processes take the cores. */
    inline double
    process_cpu_seconds()
    {
      return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
    }
  } // namespace IO
} // namespace Common

#endif
