#include "batch/isolation.h"

#include "base/errors.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>
#include <vector>

extern char **environ;

namespace gearfem::batch
{
  namespace
  {
    /// The environment of the worker: ours without what the MPI launcher set for this rank
    /// (a worker that inherited OMPI_COMM_WORLD_RANK or PMIX_* would try to join the ranks'
    /// job instead of starting as a singleton).
    std::vector<std::string> worker_environment()
    {
      std::vector<std::string> env;
      // PETSc's own signal handler would turn a crash into MPI_Abort (exit 59): without it the
      // worker ends with the signal itself, which the supervisor names.
      std::string petsc = "PETSC_OPTIONS=-no_signal_handler";
      for (char **e = environ; e && *e; ++e)
        {
          const std::string v = *e;
          if (v.rfind("PETSC_OPTIONS=", 0) == 0)
            {
              petsc += " " + v.substr(14);
              continue;
            }
          const bool launcher = v.rfind("OMPI_", 0) == 0 || v.rfind("PMIX_", 0) == 0 || v.rfind("OPAL_", 0) == 0 ||
                                v.rfind("ORTE_", 0) == 0 || v.rfind("PRTE_", 0) == 0 || v.rfind("HYDRA_", 0) == 0 ||
                                v.rfind("PMI_", 0) == 0 || v.rfind("MPI_LOCAL", 0) == 0;
          const bool keep = v.rfind("OMPI_ALLOW_RUN_AS_ROOT", 0) == 0;
          if (!launcher || keep)
            env.push_back(v);
        }
      env.push_back(petsc);
      return env;
    }

    std::filesystem::path own_executable()
    {
      std::error_code ec;
      const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
      if (ec)
        throw SolverError("batch: cannot find the gearfem executable (/proc/self/exe): " + ec.message());
      return p;
    }

    bool write_all(int fd, const std::string &s)
    {
      std::size_t done = 0;
      while (done < s.size())
        {
          const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            return false;
          done += std::size_t(n);
        }
      return true;
    }
  } // namespace

  std::string describe_signal(int signal)
  {
    const char *name = signal == SIGSEGV ? "SIGSEGV" :
                       signal == SIGABRT ? "SIGABRT" :
                       signal == SIGBUS  ? "SIGBUS" :
                       signal == SIGFPE  ? "SIGFPE" :
                       signal == SIGILL  ? "SIGILL" :
                       signal == SIGKILL ? "SIGKILL" :
                       signal == SIGTERM ? "SIGTERM" :
                                           nullptr;
    const char *what = strsignal(signal);
    return std::string(what ? what : "signal") + " (signal " + std::to_string(signal) +
           (name ? std::string(", ") + name : std::string()) + ")";
  }

  JobSupervisor::JobSupervisor(const Study &study, std::filesystem::path input_file, std::filesystem::path output_dir)
    : study_(study), input_(std::move(input_file)), output_dir_(std::move(output_dir)), root_(output_dir_ / jobs_folder)
  {
    ::signal(SIGPIPE, SIG_IGN); // a dead worker's pipe gives EPIPE, not the end of the rank
  }

  JobSupervisor::~JobSupervisor() { stop(false); }

  void JobSupervisor::start()
  {
    int jobs[2], done[2];
    if (::pipe(jobs) != 0)
      throw SolverError(std::string("batch: cannot create the worker's pipe: ") + std::strerror(errno));
    if (::pipe(done) != 0)
      {
        ::close(jobs[0]), ::close(jobs[1]);
        throw SolverError(std::string("batch: cannot create the worker's pipe: ") + std::strerror(errno));
      }
    // Our ends are not inherited by the worker (nor by a later one).
    ::fcntl(jobs[1], F_SETFD, FD_CLOEXEC);
    ::fcntl(done[0], F_SETFD, FD_CLOEXEC);
    const std::string exe = own_executable().string();
    std::vector<std::string> args = {exe, "batch", input_.string(), "--output-dir", output_dir_.string(),
                                     "--batch-worker",
                                     std::to_string(jobs[0]) + "," + std::to_string(done[1]) + "," +
                                       std::to_string(::getpid())};
    std::vector<std::string> env = worker_environment();
    std::vector<char *> argv, envp;
    for (auto &a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    for (auto &e : env)
      envp.push_back(e.data());
    envp.push_back(nullptr);
    pid_t pid    = -1;
    const int rc = ::posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), envp.data());
    ::close(jobs[0]), ::close(done[1]);
    if (rc != 0)
      {
        ::close(jobs[1]), ::close(done[0]);
        throw SolverError("batch: cannot start a worker process (" + exe + "): " + std::strerror(rc));
      }
    pid_  = pid;
    to_   = jobs[1];
    from_ = done[0];
    pending_.clear();
    ++started_;
  }

  void JobSupervisor::stop(bool kill_it)
  {
    if (to_ >= 0)
      ::close(to_);
    if (from_ >= 0)
      ::close(from_);
    to_ = from_ = -1;
    if (pid_ > 0)
      {
        if (kill_it)
          ::kill(pid_, SIGKILL);
        int st = 0;
        while (::waitpid(pid_, &st, 0) < 0 && errno == EINTR)
          {}
      }
    pid_ = -1;
  }

  JobRecord JobSupervisor::run(std::size_t i)
  {
    const auto t0     = std::chrono::steady_clock::now();
    const auto &id    = study_.designs.designs[i].id;
    const double limit = study_.batch.job_time_limit;
    auto elapsed       = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    std::string failure;
    try
      {
        if (pid_ < 0)
          start();
        (void)write_all(to_, std::to_string(i) + "\n"); // a dead worker shows as the end of its output
        const std::string want = "done " + std::to_string(i);
        while (failure.empty())
          {
            const auto nl = pending_.find('\n');
            if (nl != std::string::npos)
              {
                const std::string line = pending_.substr(0, nl);
                pending_.erase(0, nl + 1);
                if (line == want)
                  break;
                continue;
              }
            int wait_ms = -1;
            if (limit > 0)
              {
                const double left = limit - elapsed();
                if (left <= 0)
                  {
                    std::ostringstream m;
                    m << "ran over Batch/Job time limit = " << limit << " s: its worker process was killed";
                    failure = m.str();
                    stop(true);
                    break;
                  }
                wait_ms = int(std::min(left * 1000.0 + 1.0, 60000.0));
              }
            pollfd p{from_, POLLIN, 0};
            const int n = ::poll(&p, 1, wait_ms);
            if (n < 0 && errno == EINTR)
              continue;
            if (n == 0)
              continue; // the limit is checked above
            char buf[256];
            const ssize_t got = ::read(from_, buf, sizeof buf);
            if (got < 0 && errno == EINTR)
              continue;
            if (got > 0)
              {
                pending_.append(buf, std::size_t(got));
                continue;
              }
            // End of the worker's output: it has died. Why?
            int st = 0;
            while (::waitpid(pid_, &st, 0) < 0 && errno == EINTR)
              {}
            pid_ = -1;
            stop(false);
            if (WIFSIGNALED(st))
              failure = "crashed: its worker process ended with " + describe_signal(WTERMSIG(st));
            else if (WIFEXITED(st))
              failure = "its worker process exited with status " + std::to_string(WEXITSTATUS(st)) +
                        " before finishing the job";
            else
              failure = "its worker process ended before finishing the job";
          }
      }
    catch (const std::exception &e)
      {
        stop(true);
        failure = e.what();
      }
    if (failure.empty())
      if (auto rec = read_job_record(root_ / id))
        return *rec;
    if (failure.empty())
      failure = "the worker finished the job but left no job record";
    try
      {
        return record_failure(study_, i, root_, failure + " (the other jobs go on)", elapsed());
      }
    catch (const std::exception &e)
      {
        JobRecord rec;
        rec.id      = id;
        rec.message = failure + "; the record could not be written: " + e.what();
        return rec;
      }
  }

  void serve_jobs(const Study &study, const std::filesystem::path &jobs_root, int in, int out, pid_t parent)
  {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL); // die with the rank that supervises us
    if (::getppid() != parent)
      return; // the rank ended before we could ask
    ::signal(SIGPIPE, SIG_IGN);
    ModelCache cache;
    std::string buffer;
    char buf[256];
    while (true)
      {
        const auto nl = buffer.find('\n');
        if (nl == std::string::npos)
          {
            const ssize_t got = ::read(in, buf, sizeof buf);
            if (got < 0 && errno == EINTR)
              continue;
            if (got <= 0)
              return; // the supervisor closed the pipe: no more jobs
            buffer.append(buf, std::size_t(got));
            continue;
          }
        const std::string line = buffer.substr(0, nl);
        buffer.erase(0, nl + 1);
        char *end       = nullptr;
        const long long j = std::strtoll(line.c_str(), &end, 10);
        if (end == line.c_str() || j < 0 || std::size_t(j) >= study.designs.designs.size())
          return;
        (void)run_job(study, std::size_t(j), jobs_root, &cache);
        if (!write_all(out, "done " + std::to_string(j) + "\n"))
          return;
      }
  }

  void test_fault_hook(const std::string &design_id)
  {
    const char *v = std::getenv("GEARFEM_TEST_FAULT");
    if (!v)
      return;
    const std::string s = v;
    const auto colon    = s.rfind(':');
    if (colon == std::string::npos || s.substr(0, colon) != design_id)
      return;
    const std::string kind = s.substr(colon + 1);
    if (kind == "segv")
      ::raise(SIGSEGV);
    else if (kind == "abort")
      std::abort();
    else if (kind == "hang")
      while (true)
        std::this_thread::sleep_for(std::chrono::seconds(1));
  }
} // namespace gearfem::batch
