/**
 * @file tests.h
 * Minimal helpers for the deal.II-style unit tests of this suite: the test
 * driver runs each test binary in its own directory and compares the file
 * "output" there with the expected "<name>.output" (numdiff).
 */
#ifndef tests_tests_h
#define tests_tests_h

#include <deal.II/base/logstream.h>

#include <fstream>
#include <ios>

/**
 * Attach dealii::deallog to the file "output" in the current directory,
 * without job id and without console echo, and print numbers in fixed
 * notation with @p precision digits after the point. Every line comes out
 * prefixed by "DEAL:" (plus any pushed prefixes).
 */
inline void
initlog(const unsigned int precision = 6)
{
  static std::ofstream logfile("output");
  dealii::deallog.attach(logfile, false, std::ios::fixed | std::ios::left);
  dealii::deallog.depth_console(0);
  dealii::deallog.flags(std::ios::fixed | std::ios::left);
  dealii::deallog.precision(precision);
}

/**
 * Attach dealii::deallog to the file "output" in the current directory,
 * without console echo, keeping deal.II's default number format.
 */
inline void
attach_log()
{
  static std::ofstream logfile("output");
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
}

#endif
