#include "ranks/ranks.h"

#include "fem/direct_solver.h"

#include <mpi.h>

#include <chrono>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace gearfem::ranks
{
  namespace
  {
    constexpr int tag_ready = 181, tag_job = 182;

    /// The jobs not yet handed out; shared by rank 0's manager thread and its own worker.
    /// A rank that asks for a job gets the next one of the key of its last job if one is left,
    /// else the next one in order.
    class Queue
    {
    public:
      Queue(std::vector<int> jobs, std::vector<std::string> keys)
        : jobs_(std::move(jobs)), keys_(std::move(keys)), taken_(jobs_.size(), false)
      {
        keys_.resize(jobs_.size());
      }
      /// Next job for a rank whose last job had key `key` ("" none); -1 when done. `key`
      /// becomes the key of the job handed out.
      int take(std::string &key)
      {
        std::lock_guard<std::mutex> lock(m_);
        std::size_t pick = jobs_.size();
        for (std::size_t k = first_; k < jobs_.size() && !key.empty(); ++k)
          if (!taken_[k] && keys_[k] == key)
            {
              pick = k;
              break;
            }
        if (pick == jobs_.size())
          while (first_ < jobs_.size() && taken_[first_])
            ++first_;
        if (pick == jobs_.size())
          pick = first_;
        if (pick == jobs_.size())
          return -1;
        taken_[pick] = true;
        key          = keys_[pick];
        return jobs_[pick];
      }

    private:
      std::mutex m_;
      std::vector<int> jobs_;
      std::vector<std::string> keys_;
      std::vector<bool> taken_;
      std::size_t first_ = 0;
    };

    void manage(const MpiSession &mpi, const std::vector<int> &todo, const DriveOptions &o)
    {
      Queue queue(todo, o.keys);
      std::mutex report;
      const auto finished = [&](int job, const JobDone &d, int rank) {
        std::lock_guard<std::mutex> lock(report);
        if (o.finished)
          o.finished(job, d, rank);
      };
      std::map<int, std::string> rank_key; // key of each rank's last job
      const bool local = mpi.size() == 1 || o.local_worker;
      if (local && o.before_local)
        o.before_local();
      std::thread manager;
      if (mpi.size() > 1)
        manager = std::thread([&]() {
          int active = mpi.size() - 1;
          while (active > 0)
            {
              int flag = 0;
              MPI_Status st;
              MPI_Iprobe(MPI_ANY_SOURCE, tag_ready, MPI_COMM_WORLD, &flag, &st);
              if (!flag)
                {
                  std::this_thread::sleep_for(std::chrono::milliseconds(2));
                  continue;
                }
              double msg[4];
              MPI_Recv(msg, 4, MPI_DOUBLE, st.MPI_SOURCE, tag_ready, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
              if (msg[0] >= 0)
                finished(int(msg[0]), {msg[1] > 0, msg[2], msg[3] > 0}, st.MPI_SOURCE);
              int next = queue.take(rank_key[st.MPI_SOURCE]);
              MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, tag_job, MPI_COMM_WORLD);
              if (next < 0)
                --active;
            }
        });
      std::exception_ptr error;
      if (local)
        try
          {
            std::string key;
            for (int j = queue.take(key); j >= 0; j = queue.take(key))
              finished(j, o.run(j), 0);
          }
        catch (...)
          {
            error = std::current_exception(); // the other ranks still get their jobs
          }
      if (manager.joinable())
        manager.join();
      if (error)
        std::rethrow_exception(error);
    }

    void work(const DriveOptions &o)
    {
      double msg[4] = {-1, 0, 0, 0};
      while (true)
        {
          MPI_Send(msg, 4, MPI_DOUBLE, 0, tag_ready, MPI_COMM_WORLD);
          int job = -1;
          MPI_Recv(&job, 1, MPI_INT, 0, tag_job, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          if (job < 0)
            return;
          const JobDone d = o.run(job);
          msg[0] = job, msg[1] = d.ok ? 1 : 0, msg[2] = d.seconds, msg[3] = d.shared ? 1 : 0;
        }
    }
  } // namespace

  MpiSession::MpiSession()
  {
    int init = 0, provided = 0;
    MPI_Initialized(&init);
    if (!init)
      {
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
        we_initialized_ = true;
      }
    else
      MPI_Query_thread(&provided);
    multiple_ = provided >= MPI_THREAD_MULTIPLE;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }

  MpiSession::~MpiSession()
  {
    if (!we_initialized_)
      return;
    fem::finalize_petsc();
    int done = 0;
    MPI_Finalized(&done);
    if (!done)
      MPI_Finalize();
  }

  void MpiSession::barrier() const { MPI_Barrier(MPI_COMM_WORLD); }

  int MpiSession::broadcast(int value) const
  {
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
  }

  void drive(const MpiSession &mpi, const std::vector<int> &todo, const DriveOptions &options)
  {
    if (mpi.rank() == 0)
      manage(mpi, todo, options);
    else
      work(options);
  }
} // namespace gearfem::ranks
