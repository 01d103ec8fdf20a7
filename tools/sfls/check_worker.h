// The checks of documents, on a thread of their own so that the thread that
// reads messages never waits for one. Each document has at most one check
// waiting: a newer version replaces it unchecked, so that a burst of edits
// costs one check of the last, and stops the check of an older version
// that is running (ReadOptions::stop), so that the newest waits for no
// stale one to finish. A check waits an eighth of the document's last
// check's time (at most 150 ms) for a further edit, as clangd's debounce
// does: while keys are typed into a large document, no check holds its
// text, which each edit then changes in place rather than copies.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "tools/sfls/analysis.h"

namespace sfls {

struct CheckJob {
  using Clock = std::chrono::steady_clock;
  std::string uri;
  std::int64_t version = 0;
  std::shared_ptr<const std::string> text;
  // The document's file, whose name decides what the content leaves open and
  // whose folder OUTPUT_FILE is taken in; empty for a document with none.
  std::filesystem::path file;
};

// sfcheck's check of `job`'s text (tools::checkDocument) and its outline.
// Once `stop` is requested the check ends early with a partial result.
std::shared_ptr<Analysis> analyse(const CheckJob& job, std::stop_token stop = {});

class CheckWorker {
 public:
  // `checked` is called on the worker's thread with each finished check.
  using Checked = std::function<void(const std::string& uri, std::shared_ptr<Analysis>)>;

  // The longest a check waits for a further edit.
  static constexpr std::chrono::milliseconds kMaxWait{150};

  explicit CheckWorker(Checked checked);
  ~CheckWorker();
  CheckWorker(const CheckWorker&) = delete;
  CheckWorker& operator=(const CheckWorker&) = delete;

  void schedule(CheckJob job);
  // Drops the document's waiting check and stops its running one (the
  // document changed again).
  void forget(const std::string& uri);
  // The same, and forgets how long its checks took (it was closed).
  void close(const std::string& uri);
  // Frees `analysis` on the worker's thread, before its next check: the
  // scene of a million objects takes tens of milliseconds to free, which
  // the thread that answers requests should not spend.
  void release(std::shared_ptr<Analysis> analysis);

 private:
  void work();

  Checked checked_;
  std::mutex mutex_;
  std::condition_variable wake_;
  // A job, and when it may start.
  struct Waiting {
    CheckJob job;
    CheckJob::Clock::time_point notBefore;
  };
  std::vector<Waiting> waiting_;
  std::vector<std::shared_ptr<Analysis>> released_;
  // The document being checked, and how to stop that check.
  std::string runningUri_;
  std::stop_source runningStop_;
  // How long each document's last finished check took.
  std::map<std::string, CheckJob::Clock::duration> lastTook_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace sfls
