#pragma once
// Shared test inputs (tests/data/): read a fixture file into a string, so that the test
// cases that use the same pair state it once. The source folder comes from the
// GEARFEM_SOURCE_DIR environment variable (set by CTest) or, when a test executable is run
// by hand or by a validation script, from the compile-time GEARFEM_TEST_SOURCE_DIR.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gearfem::test
{
  inline std::string source_dir()
  {
    if (const char *s = std::getenv("GEARFEM_SOURCE_DIR"))
      return s;
#ifdef GEARFEM_TEST_SOURCE_DIR
    return GEARFEM_TEST_SOURCE_DIR;
#else
    return ".";
#endif
  }

  /// The text of tests/data/<name>.
  inline std::string fixture(const std::string &name)
  {
    const std::string path = source_dir() + "/tests/data/" + name;
    std::ifstream in(path);
    if (!in)
      throw std::runtime_error("test fixture not found: " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /// The Parker 50/50 m 3 pair (tests/data/parker_pair.prm) followed by `sections`.
  inline std::string parker_pair(const std::string &sections = {})
  {
    return fixture("parker_pair.prm") + sections;
  }
} // namespace gearfem::test
