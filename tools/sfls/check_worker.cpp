#include "tools/sfls/check_worker.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>

#include "tools/common/document_check.h"

namespace sfls {
namespace {

constexpr int kCheckNiceness = 10;

}  // namespace

std::shared_ptr<Analysis> analyse(const CheckJob& job, std::stop_token stop) {
  auto start = std::chrono::steady_clock::now();
  std::string shownName = job.file.empty() ? job.uri : job.file.string();
  scene::ReadOptions options;
  options.stop = stop;
  tools::DocumentCheck check =
      tools::checkDocument(*job.text, shownName, job.file.parent_path(), options);
  auto analysis = std::make_shared<Analysis>();
  analysis->version = job.version;
  analysis->text = job.text;
  analysis->format = check.format;
  analysis->result = std::move(check.result);
  if (stop.stop_requested()) return analysis;
  if (check.format == scene::Format::SceneFile || check.format == scene::Format::InstructionFile) {
    analysis->outline = scene::outlineOf(*job.text, *check.format);
  }
  analysis->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return analysis;
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
    auto same = std::find_if(waiting_.begin(), waiting_.end(),
                             [&](const CheckJob& other) { return other.uri == job.uri; });
    if (job.uri == runningUri_) runningStop_.request_stop();
    if (same != waiting_.end()) {
      *same = std::move(job);
    } else {
      waiting_.push_back(std::move(job));
    }
  }
  wake_.notify_one();
}

void CheckWorker::forget(const std::string& uri) {
  std::lock_guard lock(mutex_);
  if (uri == runningUri_) runningStop_.request_stop();
  std::erase_if(waiting_, [&](const CheckJob& job) { return job.uri == uri; });
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
      wake_.wait(lock, [this] { return stopping_ || !waiting_.empty() || !released_.empty(); });
      if (stopping_) return;
      released.swap(released_);
      if (waiting_.empty()) continue;
      job = std::move(waiting_.front());
      waiting_.erase(waiting_.begin());
      runningUri_ = job.uri;
      runningStop_ = std::stop_source();
      stop = runningStop_.get_token();
    }
    released.clear();
    std::shared_ptr<Analysis> analysis = analyse(job, stop);
    {
      std::lock_guard lock(mutex_);
      runningUri_.clear();
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
