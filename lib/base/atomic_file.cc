#include "base/atomic_file.h"

#include <atomic>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace gearfem
{
  namespace
  {
    std::atomic<unsigned> counter{0};
  }

  TemporaryPath::TemporaryPath(const std::filesystem::path &target)
    : target_(target)
  {
    tmp_ = target;
    tmp_ += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  }

  TemporaryPath::~TemporaryPath()
  {
    if (!committed_)
      {
        std::error_code ec;
        std::filesystem::remove(tmp_, ec);
      }
  }

  void TemporaryPath::commit()
  {
    if (!std::filesystem::exists(tmp_))
      throw std::runtime_error("output file was not produced: " + target_.string());
    std::filesystem::rename(tmp_, target_);
    committed_ = true;
  }

  AtomicOutputFile::AtomicOutputFile(const std::filesystem::path &target)
    : tmp_(target)
    , out_(tmp_.path())
  {
    if (!out_)
      throw std::runtime_error("cannot open for writing: " + tmp_.path().string());
  }

  void AtomicOutputFile::commit()
  {
    out_.flush();
    if (!out_)
      throw std::runtime_error("write failed: " + tmp_.target().string());
    out_.close();
    tmp_.commit();
  }

  void write_file_atomically(const std::filesystem::path &target, const std::string &content)
  {
    AtomicOutputFile f(target);
    f << content;
    f.commit();
  }
} // namespace gearfem
