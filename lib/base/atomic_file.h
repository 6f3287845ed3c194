#pragma once
// Atomic output: every file gearfem writes goes to a temporary name in the same folder
// and is renamed into place only when complete, so an interrupted or failed run never
// leaves a truncated file behind.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>

namespace gearfem
{
  /// A temporary path beside `target`. commit() renames it onto `target`; if the object
  /// is destroyed without commit(), the temporary file is removed.
  class TemporaryPath
  {
  public:
    explicit TemporaryPath(const std::filesystem::path &target);
    ~TemporaryPath();
    TemporaryPath(const TemporaryPath &) = delete;
    TemporaryPath &operator=(const TemporaryPath &) = delete;

    const std::filesystem::path &path() const { return tmp_; }
    const std::filesystem::path &target() const { return target_; }
    /// Rename the temporary file onto the target. Throws std::runtime_error if the
    /// temporary file does not exist.
    void commit();

  private:
    std::filesystem::path target_, tmp_;
    bool committed_ = false;
  };

  /// An output stream whose content appears at `target` only on commit().
  class AtomicOutputFile
  {
  public:
    explicit AtomicOutputFile(const std::filesystem::path &target);
    std::ofstream &stream() { return out_; }
    template <typename T>
    AtomicOutputFile &operator<<(const T &v)
    {
      out_ << v;
      return *this;
    }
    /// Flush, check the stream state, close and rename into place.
    void commit();

  private:
    TemporaryPath tmp_;
    std::ofstream out_;
  };

  /// Write `target` atomically through `body(std::ostream &)`, numbers with `digits`
  /// significant digits.
  template <typename F>
  void write_atomically(const std::filesystem::path &target, F &&body, int digits = 10)
  {
    AtomicOutputFile f(target);
    f.stream() << std::setprecision(digits);
    body(f.stream());
    f.commit();
  }

  /// Write `content` to `target` atomically.
  void write_file_atomically(const std::filesystem::path &target, const std::string &content);
} // namespace gearfem
