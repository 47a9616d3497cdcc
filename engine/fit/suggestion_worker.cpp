#include "engine/fit/suggestion_worker.hpp"

#include <pthread.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <exception>
#include <map>
#include <mutex>

#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include "engine/geometry/symmetry.hpp"

namespace curvefold {

namespace {

pid_t threadId() {
  return pid_t(syscall(SYS_gettid));
}

int threadNice() {
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, id_t(threadId()));
  return errno == 0 ? nice : 0;
}

void setThreadNice(int nice) {
  setpriority(PRIO_PROCESS, id_t(threadId()), nice);
}

// TBB's workers that join the search's arena run at `nice` while in it, and go back to their own
// when they leave where the system lets them (going back up needs CAP_SYS_NICE or RLIMIT_NICE:
// without, a worker stays at `nice`, which only slows other parallel work when the cores are
// contended).
class NiceWhileSearching : public tbb::task_scheduler_observer {
 public:
  NiceWhileSearching(tbb::task_arena& arena, int nice)
      : tbb::task_scheduler_observer(arena), nice_(nice) {
    observe(true);
  }
  void on_scheduler_entry(bool worker) override {
    if (!worker) return;
    before_ = threadNice();
    if (before_ < nice_) setThreadNice(nice_);
  }
  void on_scheduler_exit(bool worker) override {
    if (worker && before_ < nice_) setThreadNice(before_);
  }

 private:
  const int nice_;
  static thread_local int before_;
};
thread_local int NiceWhileSearching::before_ = 0;

// The arena the searches at `nice` run in, with its observer: one per nice for the whole process,
// never taken down. TBB (2021.8) can lose an observer's record when observe(false) or the arena's
// end races a worker still leaving it (LeakSanitizer caught it in CI), and an arena that lives on
// has no such end.
tbb::task_arena& searchArena(int nice) {
  struct Lowered {
    explicit Lowered(int nice) : observer(arena, nice) {}
    tbb::task_arena arena{};
    NiceWhileSearching observer;
  };
  static std::mutex mutex;
  static std::map<int, Lowered*>& arenas = *new std::map<int, Lowered*>;  // never destroyed
  const std::lock_guard lock(mutex);
  Lowered*& lowered = arenas[nice];
  if (lowered == nullptr) lowered = new Lowered(nice);
  return lowered->arena;
}

}  // namespace

void runAtSearchNice(int nice, const std::function<void()>& work) {
  if (nice <= 0) {
    work();
    return;
  }
  if (threadNice() < nice) setThreadNice(nice);
  searchArena(nice).execute(work);
}

SuggestionWorker::SuggestionWorker(std::shared_ptr<const FoldFitter> fitter, double timeLimit,
                                   int nice)
    : fitter_(std::move(fitter)), timeLimit_(timeLimit), nice_(nice), thread_([this] { run(); }) {}

SuggestionWorker::~SuggestionWorker() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    abandon_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

std::uint64_t SuggestionWorker::request(DesignSnapshot design, std::size_t count) {
  std::uint64_t number = 0;
  {
    const std::lock_guard lock(mutex_);
    number = ++latest_;
    pending_.emplace(std::move(design), count);
    answer_.reset();
    if (working_ != 0) abandon_ = true;  // the search in flight is for an older design
  }
  wake_.notify_one();
  return number;
}

void SuggestionWorker::cancel() {
  const std::lock_guard lock(mutex_);
  ++latest_;  // an answer on its way is of no request now
  pending_.reset();
  answer_.reset();
  if (working_ != 0) abandon_ = true;
}

void SuggestionWorker::retarget(std::shared_ptr<const FoldFitter> fitter) {
  const std::lock_guard lock(mutex_);
  fitter_ = std::move(fitter);
  ++latest_;
  pending_.reset();
  answer_.reset();
  if (working_ != 0) abandon_ = true;
}

std::uint64_t SuggestionWorker::searching() const {
  const std::lock_guard lock(mutex_);
  return working_;
}

bool SuggestionWorker::busy() const {
  const std::lock_guard lock(mutex_);
  return pending_.has_value() || working_ != 0;
}

std::optional<SuggestionWorker::Answer> SuggestionWorker::take() {
  const std::lock_guard lock(mutex_);
  std::optional<Answer> answer = std::move(answer_);
  answer_.reset();
  return answer;
}

bool SuggestionWorker::replay(FoldSession& session, const std::vector<FoldRecord>& folds) const {
  std::size_t made = 0;
  while (made < folds.size()) {
    if (abandon_.load(std::memory_order_relaxed)) return false;
    // As many folds as the sheet's triangles allow per check (folds grow it: counted anew).
    const std::size_t triangles = std::max<std::size_t>(1, session.fixed().triangleCount());
    const std::size_t count =
        std::clamp<std::size_t>(kReplayTrianglesPerCheck / triangles, 1, folds.size() - made);
    const auto from = folds.begin() + static_cast<std::ptrdiff_t>(made);
    session.applyRecords({from, from + static_cast<std::ptrdiff_t>(count)});
    made += count;
  }
  return true;
}

void SuggestionWorker::run() {
  // Named, so a profile or the window's --frame-times can tell the search's CPU from the rest.
  pthread_setname_np(pthread_self(), "cf-search");
  // This thread only searches: it stays at nice_, and the TBB workers in its arena go to it.
  if (threadNice() < nice_) setThreadNice(nice_);
  tbb::task_arena& arena = searchArena(nice_);
  while (true) {
    std::pair<DesignSnapshot, std::size_t> job;
    std::shared_ptr<const FoldFitter> fitter;
    std::uint64_t number = 0;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || pending_.has_value(); });
      if (stopping_) return;
      job = std::move(*pending_);
      pending_.reset();
      number = working_ = latest_;
      fitter = fitter_;
      abandon_ = false;
    }
    Answer answer;
    answer.request = number;
    try {
      // The search drags and commits on a session of its own, never on the studio's.
      FoldSession session(*job.first.initial);
      if (!job.first.symmetry.empty())
        session.setSymmetry(parseSymmetry(job.first.symmetry, session.initial()));
      if (!replay(session, job.first.folds)) {
        const std::lock_guard lock(mutex_);
        working_ = 0;  // abandoned while its design was made: nothing to answer
        continue;
      }
      Deadline deadline = Deadline::in(timeLimit_);
      deadline.cancelled = &abandon_;
      deadline.answerLate = true;  // out of time, the best scored so far
      arena.execute([&] { answer.suggestions = fitter->suggest(session, job.second, deadline); });
    } catch (const std::exception& e) {
      answer.error = e.what();
    }
    const std::lock_guard lock(mutex_);
    // An abandoned search's result is of an older design: dropped.
    if (!abandon_ && number == latest_) answer_ = std::move(answer);
    working_ = 0;
  }
}

}  // namespace curvefold
