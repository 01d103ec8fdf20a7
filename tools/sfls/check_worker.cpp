#include "tools/sfls/check_worker.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace sfls {
namespace {

constexpr int kCheckNiceness = 10;

}  // namespace

std::shared_ptr<Analysis> analyse(const CheckJob& job, std::stop_token stop) {
  std::string shownName = job.file.empty() ? job.uri : job.file.string();
  scene::ReadOptions options;
  options.stop = stop;
  return analyseText(job.text, job.version, shownName, job.file.parent_path(), options);
}

CheckWorker::CheckWorker(Checked checked) : checked_(std::move(checked)) {
  thread_ = std::thread([this] { work(); });
}

CheckWorker::~CheckWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    runningStop_.request_stop();
  }
  wake_.notify_all();
  thread_.join();
}

void CheckWorker::schedule(CheckJob job) {
  {
    std::lock_guard lock(mutex_);
    auto took = lastTook_.find(job.uri);
    auto delay = took == lastTook_.end() ? CheckJob::Clock::duration::zero() : took->second / 8;
    auto notBefore = CheckJob::Clock::now() + std::min<CheckJob::Clock::duration>(delay, kMaxWait);
    auto same = std::find_if(waiting_.begin(), waiting_.end(),
                             [&](const Waiting& other) { return other.job.uri == job.uri; });
    if (job.uri == runningUri_) runningStop_.request_stop();
    if (same != waiting_.end()) {
      *same = {std::move(job), notBefore};
    } else {
      waiting_.push_back({std::move(job), notBefore});
    }
  }
  wake_.notify_one();
}

void CheckWorker::forget(const std::string& uri) {
  std::lock_guard lock(mutex_);
  if (uri == runningUri_) runningStop_.request_stop();
  std::erase_if(waiting_, [&](const Waiting& waiting) { return waiting.job.uri == uri; });
}

void CheckWorker::close(const std::string& uri) {
  forget(uri);
  std::lock_guard lock(mutex_);
  lastTook_.erase(uri);
}

void CheckWorker::release(std::shared_ptr<Analysis> analysis) {
  {
    std::lock_guard lock(mutex_);
    released_.push_back(std::move(analysis));
  }
  wake_.notify_one();
}

void CheckWorker::work() {
  // A check of a large file takes every core (ReadOptions::threads 0) for
  // a second; at a lower priority, which the reader's threads inherit from
  // this one, it leaves the handling thread the core it needs to answer
  // hover and completion meanwhile. A failure leaves the priority as it is.
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kCheckNiceness);
  for (;;) {
    CheckJob job;
    std::stop_token stop;
    std::vector<std::shared_ptr<Analysis>> released;
    {
      std::unique_lock lock(mutex_);
      auto ready = waiting_.end();
      auto wakeAt = CheckJob::Clock::time_point::max();
      // The first job whose time has come, else a wait until the earliest
      // one's, or until a job, a release or the end comes.
      auto look = [&] {
        if (stopping_ || !released_.empty()) return true;
        auto now = CheckJob::Clock::now();
        wakeAt = CheckJob::Clock::time_point::max();
        ready = std::find_if(waiting_.begin(), waiting_.end(),
                             [&](const Waiting& waiting) { return waiting.notBefore <= now; });
        for (const Waiting& waiting : waiting_) wakeAt = std::min(wakeAt, waiting.notBefore);
        return ready != waiting_.end();
      };
      while (!look()) {
        if (wakeAt == CheckJob::Clock::time_point::max()) {
          wake_.wait(lock);
        } else {
          wake_.wait_until(lock, wakeAt);
        }
      }
      if (stopping_) return;
      released.swap(released_);
      if (ready == waiting_.end()) continue;
      job = std::move(ready->job);
      waiting_.erase(ready);
      runningUri_ = job.uri;
      runningStop_ = std::stop_source();
      stop = runningStop_.get_token();
    }
    released.clear();
    auto start = CheckJob::Clock::now();
    std::shared_ptr<Analysis> analysis = analyse(job, stop);
    {
      std::lock_guard lock(mutex_);
      runningUri_.clear();
      if (!stop.stop_requested()) lastTook_[job.uri] = CheckJob::Clock::now() - start;
    }
    // A stopped check is partial and of a text the document has left.
    if (stop.stop_requested()) continue;
    // The job's hold on the text ends here; the analysis keeps it only if
    // it is still the document's latest (the server decides).
    job.text.reset();
    checked_(job.uri, std::move(analysis));
  }
}

}  // namespace sfls
