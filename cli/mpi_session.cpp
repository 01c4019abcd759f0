#include "cli/mpi_session.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#ifdef SPIFIT_HAVE_MPI
#include <mpi.h>

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <future>
#include <mutex>
#include <vector>
#endif

namespace spifit::cli::mpi {

namespace {

int g_rank = 0, g_size = 1;
[[maybe_unused]] bool g_started = false, g_stopped = false, g_skip_finalize = false;

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

int rank() { return g_rank; }
int size() { return g_size; }

#ifdef SPIFIT_HAVE_MPI

namespace {

constexpr int kJob = 1, kAnswer = 2, kStop = 3, kAlive = 4;
constexpr auto kPoll = std::chrono::microseconds(500);
// A worker busy with a job says it is alive every kAliveEvery; rank 0 counts one that has not for
// kDeadAfter as dead (its process or node has gone; under mpirun with orte_enable_recovery the
// other ranks go on).
// kDeadAfter: 30 s, or SPIFIT_MPI_DEAD_AFTER seconds (at least 5).
constexpr auto kAliveEvery = std::chrono::seconds(2);
std::chrono::seconds dead_after() {
  const char* v = std::getenv("SPIFIT_MPI_DEAD_AFTER");
  const int s = v ? std::atoi(v) : 0;
  return std::chrono::seconds(s >= 5 ? s : 30);
}
const std::chrono::seconds kDeadAfter = dead_after();

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
// A job whose rank dies goes back to the front of the queue once; lost twice, its caller gets an
// exception (a failed run to a fit or a sweep).
class MpiPool final : public inverse::JobPool {
 public:
  explicit MpiPool(int ranks) : workers_(static_cast<std::size_t>(ranks)) { thread_ = std::thread([this] { loop(); }); }
  ~MpiPool() override { stop(); }
  int workers() const override { return static_cast<int>(workers_.size()) - 1; }
  std::string run(const std::string& job) override {
    std::promise<std::string> answer;
    auto f = answer.get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) throw std::runtime_error("the MPI pool has stopped");
      queue_.push_back({job, std::move(answer), 0});
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
  // Ranks found dead (not to be sent anything, the stop included).
  std::vector<int> dead() const {
    std::vector<int> out;
    for (std::size_t r = 1; r < workers_.size(); ++r)
      if (workers_[r].dead) out.push_back(static_cast<int>(r));
    return out;
  }

 private:
  struct Pending {
    std::string job;
    std::promise<std::string> answer;
    int lost = 0;  // times its rank died running it
  };
  struct Worker {
    bool busy = false, dead = false;
    Pending job;
    std::chrono::steady_clock::time_point seen;
  };
  // Jobs to idle ranks, lowest rank first; whether any was sent.
  bool hand_out() {
    bool sent = false;
    for (std::size_t r = 1; r < workers_.size(); ++r) {
      Worker& w = workers_[r];
      if (w.busy || w.dead) continue;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (queue_.empty()) break;
        w.job = std::move(queue_.front());
        queue_.pop_front();
      }
      send(w.job.job, static_cast<int>(r), kJob);
      w.busy = true;
      w.seen = std::chrono::steady_clock::now();
      sent = true;
    }
    return sent;
  }
  // A busy rank silent for kDeadAfter: dead; its job back to the queue once.
  void bury_the_silent() {
    const auto now = std::chrono::steady_clock::now();
    for (std::size_t r = 1; r < workers_.size(); ++r) {
      Worker& w = workers_[r];
      if (!w.busy || now - w.seen < kDeadAfter) continue;
      w.dead = true;
      w.busy = false;
      std::fprintf(stderr, "spifit: rank %zu has not answered for %lld s: counted as dead\n", r,
                   static_cast<long long>(std::chrono::duration_cast<std::chrono::seconds>(kDeadAfter).count()));
      if (++w.job.lost < 2) {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.push_front(std::move(w.job));
      } else {
        w.job.answer.set_exception(std::make_exception_ptr(std::runtime_error("two ranks died running this job")));
      }
    }
    bool alive = false;
    for (std::size_t r = 1; r < workers_.size(); ++r) alive = alive || !workers_[r].dead;
    if (alive) return;
    std::lock_guard<std::mutex> lock(mutex_);  // no worker left: nothing queued can run
    for (auto& p : queue_) p.answer.set_exception(std::make_exception_ptr(std::runtime_error("every worker rank has died")));
    queue_.clear();
  }
  void loop() {
    for (;;) {
      bool active = hand_out();
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        const auto r = static_cast<std::size_t>(st.MPI_SOURCE);
        std::string bytes = receive(st.MPI_SOURCE, st.MPI_TAG, &st);
        Worker& w = workers_[r];
        w.seen = std::chrono::steady_clock::now();
        if (st.MPI_TAG == kAnswer && w.busy && !w.dead) {
          w.busy = false;
          w.job.answer.set_value(std::move(bytes));
        }
        active = true;
      }
      bury_the_silent();
      bool idle = true;
      for (const Worker& w : workers_) idle = idle && !w.busy;
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
  std::vector<Worker> workers_;  // by rank (0 unused); the pool thread's only
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
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);  // a dead rank is rank 0's to handle
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
      g_skip_finalize = !bytes.empty();
      return;
    }
    // The job on a thread of its own; this one (the only one calling MPI) says it is alive.
    auto answer = std::async(std::launch::async, [&handler, &bytes] { return handler(bytes); });
    auto next = std::chrono::steady_clock::now() + kAliveEvery;
    while (answer.wait_until(next) != std::future_status::ready) {
      send(std::string(), 0, kAlive);
      next += kAliveEvery;
    }
    send(answer.get(), 0, kAnswer);
  }
}

void finish() {
  if (!g_started) return;
  if (g_rank == 0) {
    std::vector<int> dead;
    if (g_pool) {
      g_pool->stop();
      dead = g_pool->dead();
    }
    // With a dead rank MPI_Finalize would wait for it for ever (its fence spans every rank): the
    // stop then tells the others to end without it, as this rank does.
    const std::string stop = dead.empty() ? "" : "without finalize";
    for (int r = 1; r < g_size; ++r)
      if (std::find(dead.begin(), dead.end(), r) == dead.end()) send(stop, r, kStop);
    g_skip_finalize = !dead.empty();
  } else {
    // A worker that never served (its command ended early): answer nothing, wait for the stop.
    serve([](const std::string&) { return std::string(); });
  }
  g_pool.reset();
  g_started = false;
  if (g_skip_finalize) {
    std::fflush(nullptr);
    return;
  }
  MPI_Finalize();
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
