#include "cli/mpi_session.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#ifdef SPIFIT_HAVE_MPI
#include <mpi.h>

#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <vector>
#endif

namespace spifit::cli::mpi {

namespace {

int g_rank = 0, g_size = 1;
[[maybe_unused]] bool g_started = false, g_stopped = false;

// Whether a launcher started this process as one of several (Open MPI's mpirun, Slurm's srun,
// any PMIx launcher).
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    const char* s = std::getenv(v);
    if (s && *s) return std::string(v) == "PMIX_RANK" || std::atoi(s) > 1;
  }
  return false;
}

}  // namespace

bool built_with_mpi() {
#ifdef SPIFIT_HAVE_MPI
  return true;
#else
  return false;
#endif
}

int rank() { return g_rank; }
int size() { return g_size; }

#ifdef SPIFIT_HAVE_MPI

namespace {

constexpr int kJob = 1, kAnswer = 2, kStop = 3;
constexpr auto kPoll = std::chrono::microseconds(500);

std::string receive(int source, int tag, MPI_Status* st) {
  int n = 0;
  MPI_Get_count(st, MPI_CHAR, &n);
  std::string bytes(static_cast<std::size_t>(n), '\0');
  MPI_Recv(bytes.data(), n, MPI_CHAR, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return bytes;
}

void send(const std::string& bytes, int dest, int tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

// Rank 0's pool: callers queue jobs; one thread sends them to idle ranks and hands back answers.
class MpiPool final : public inverse::JobPool {
 public:
  explicit MpiPool(int ranks) : busy_(static_cast<std::size_t>(ranks), false), waiting_(static_cast<std::size_t>(ranks)) {
    thread_ = std::thread([this] { loop(); });
  }
  ~MpiPool() override { stop(); }
  int workers() const override { return static_cast<int>(busy_.size()) - 1; }
  std::string run(const std::string& job) override {
    std::promise<std::string> answer;
    auto f = answer.get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) throw std::runtime_error("the MPI pool has stopped");
      queue_.push_back({job, std::move(answer)});
    }
    return f.get();
  }
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    if (thread_.joinable()) thread_.join();
  }

 private:
  struct Pending {
    std::string job;
    std::promise<std::string> answer;
  };
  void loop() {
    for (;;) {
      bool active = false;
      // Jobs to idle ranks, lowest rank first.
      for (std::size_t r = 1; r < busy_.size(); ++r) {
        if (busy_[r]) continue;
        Pending p;
        {
          std::lock_guard<std::mutex> lock(mutex_);
          if (queue_.empty()) break;
          p = std::move(queue_.front());
          queue_.pop_front();
        }
        send(p.job, static_cast<int>(r), kJob);
        busy_[r] = true;
        waiting_[r] = std::move(p.answer);
        active = true;
      }
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, kAnswer, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        const int r = st.MPI_SOURCE;
        std::string bytes = receive(r, kAnswer, &st);
        busy_[static_cast<std::size_t>(r)] = false;
        waiting_[static_cast<std::size_t>(r)].set_value(std::move(bytes));
        active = true;
      }
      bool idle = true;
      for (bool b : busy_) idle = idle && !b;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_ && idle && queue_.empty()) return;
      }
      if (!active) std::this_thread::sleep_for(kPoll);
    }
  }
  std::mutex mutex_;
  std::deque<Pending> queue_;
  bool stopping_ = false;
  std::vector<bool> busy_;  // by rank (0 unused); the pool thread's only
  std::vector<std::promise<std::string>> waiting_;
  std::thread thread_;
};

std::shared_ptr<MpiPool> g_pool;

// Waits for a message from rank 0 (polling); its tag.
int next_message(MPI_Status* st) {
  for (;;) {
    int flag = 0;
    MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, st);
    if (flag) return st->MPI_TAG;
    std::this_thread::sleep_for(kPoll);
  }
}

}  // namespace

void start(int* argc, char*** argv) {
  if (g_started || !launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
  g_started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
  if (provided < MPI_THREAD_SERIALIZED && g_size > 1)
    throw std::runtime_error("MPI gives no MPI_THREAD_SERIALIZED support, which the pool of forward runs needs");
}

std::shared_ptr<inverse::JobPool> pool() {
  if (!g_started || g_size < 2 || g_rank != 0) return nullptr;
  if (!g_pool) g_pool = std::make_shared<MpiPool>(g_size);
  return g_pool;
}

void serve(const inverse::JobHandler& handler) {
  if (!g_started || g_rank == 0 || g_stopped) return;
  for (;;) {
    MPI_Status st;
    const int tag = next_message(&st);
    std::string bytes = receive(0, tag, &st);
    if (tag == kStop) {
      g_stopped = true;
      return;
    }
    send(handler(bytes), 0, kAnswer);
  }
}

void finish() {
  if (!g_started) return;
  if (g_rank == 0) {
    if (g_pool) g_pool->stop();
    for (int r = 1; r < g_size; ++r) send(std::string(), r, kStop);
  } else {
    // A worker that never served (its command ended early): answer nothing, wait for the stop.
    serve([](const std::string&) { return std::string(); });
  }
  g_pool.reset();
  MPI_Finalize();
  g_started = false;
}

#else  // a build without MPI: always one process

void start(int*, char***) {
  if (launched_by_mpi())
    throw std::runtime_error("this spifit was built without MPI (Open MPI was not found when it was built), so it runs one process only");
}
void finish() {}
std::shared_ptr<inverse::JobPool> pool() { return nullptr; }
void serve(const inverse::JobHandler&) {}

#endif

}  // namespace spifit::cli::mpi
