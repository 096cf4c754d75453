/**
 * What the unit tests of the mesh file readers share (msh_file,
 * msh_file_errors, inp_file, inp_file_errors; std only, no deal.II): the
 * count of checks, a temporary folder for the files they write, the
 * replacement of one piece of a text, and the check that reading a file
 * fails at the right line with the right message.
 */

#ifndef tribos_tests_reader_check_h
#define tribos_tests_reader_check_h

#include <tribos/scene/msh_file.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <string>

namespace reader_check
{
  namespace fs = std::filesystem;

  inline unsigned int n_passed = 0, n_failed = 0;
  /** The temporary files' folder. */
  inline fs::path directory;

  inline void
  check(const bool ok, const std::string &what)
  {
    if (ok)
      ++n_passed;
    else
    {
      ++n_failed;
      std::cout << "FAILED: " << what << std::endl;
    }
  }

  /** Write @p text to the file @p name of the temporary folder. */
  inline std::string
  write(const std::string &name, const std::string &text)
  {
    const fs::path path = directory / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  /** @p text with its single occurrence of @p from replaced by @p to. */
  inline std::string
  replace(std::string text, const std::string &from, const std::string &to)
  {
    const std::size_t at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos)
    {
      std::cout << "test error: '" << from << "' is not in the text once\n";
      std::exit(2);
    }
    return text.replace(at, from.size(), to);
  }

  /**
   * @p read must fail with an MshError in the file @p in at @p line, with
   * @p expected in its message and "<in>:<line>: <message>" as its what().
   */
  inline void
  expect_error_in(const std::string           &name,
                  const std::function<void()> &read,
                  const std::string           &in,
                  const std::size_t            line,
                  const std::string           &expected)
  {
    try
    {
      read();
      check(false,
            name + ": read without error; expected line " +
              std::to_string(line) + ": " + expected);
    }
    catch (const tribos::MshError &e)
    {
      const std::string what =
        in + ":" + std::to_string(e.line()) + ": " + e.message();
      check(e.line() == line &&
              e.message().find(expected) != std::string::npos &&
              e.file() == in && e.what() == what,
            name + ": expected " + in + ":" + std::to_string(line) + " and '" +
              expected + "', got: " + e.what());
    }
    catch (const std::exception &e)
    {
      check(false, name + ": not an MshError: " + e.what());
    }
  }

  /**
   * The main function of a reader test called @p name: @p tests run with
   * a fresh temporary folder (removed afterwards), then "N passed, N
   * failed"; the exit status is 0 if none failed.
   */
  inline int
  run(const std::string &name, const std::function<void()> &tests)
  {
    directory =
      fs::temp_directory_path() /
      ("tribos_" + name + "_" + std::to_string(std::random_device()()) + "_" +
       std::to_string(
         std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(directory);
    tests();
    std::error_code error;
    fs::remove_all(directory, error);
    std::cout << n_passed << " passed, " << n_failed << " failed" << std::endl;
    return n_failed == 0 ? 0 : 1;
  }
} // namespace reader_check

#endif
