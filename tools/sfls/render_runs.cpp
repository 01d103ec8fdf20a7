#include "tools/sfls/render_runs.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <thread>

namespace sfls {
namespace {

// How long a render waits for the client to accept its progress token
// before it starts without one.
constexpr auto kTokenWait = std::chrono::seconds(5);
// $/progress reports no more often than this: a client redraws on each.
constexpr auto kReportInterval = std::chrono::milliseconds(100);

}  // namespace

struct RenderRuns::Run {
  nlohmann::json id;
  nlohmann::json token;     // null: no progress is told
  nlohmann::json createId;  // the create request's id, where one was sent
  render::CancelFlag cancel;
  std::mutex mutex;
  std::condition_variable answered;
  bool tokenAnswered = false;
  bool tokenAccepted = false;
  std::atomic<bool> finished{false};
  std::thread thread;
};

RenderRuns::~RenderRuns() {
  stopAll();
}

void RenderRuns::start(const nlohmann::json& id, RenderRequest request,
                       const nlohmann::json& clientToken, bool createToken) {
  reapFinished();
  auto run = std::make_shared<Run>();
  run->id = id;
  if (!clientToken.is_null()) {
    run->token = clientToken;
    run->tokenAnswered = true;
    run->tokenAccepted = true;
  } else if (createToken) {
    std::uint64_t n = ++tokens_;
    run->token = "scenefile.render/" + std::to_string(n);
    run->createId = "sfls-progress-" + std::to_string(n);
    writer_.send(
        requestMessage(run->createId, "window/workDoneProgress/create", {{"token", run->token}}));
  }
  {
    std::lock_guard lock(mutex_);
    runs_.push_back(run);
  }
  run->thread = std::thread([this, run, request = std::move(request)] {
    execute(*run, request);
    run->finished = true;
  });
}

void RenderRuns::execute(Run& run, const RenderRequest& request) {
  bool progress = false;
  if (!run.token.is_null()) {
    std::unique_lock lock(run.mutex);
    progress = run.answered.wait_for(lock, kTokenWait, [&] {
      return run.tokenAnswered || run.cancel.requested();
    }) && run.tokenAccepted;
  }
  auto tell = [&](nlohmann::json value) {
    if (progress)
      writer_.send(
          notificationMessage("$/progress", {{"token", run.token}, {"value", std::move(value)}}));
  };
  tell({{"kind", "begin"}, {"title", "Rendering"}, {"cancellable", true}, {"percentage", 0}});
  std::mutex reportMutex;
  auto lastReport = std::chrono::steady_clock::now();
  int lastPercentage = 0;
  RenderOutcome outcome = renderDocument(
      request,
      [&](double fraction, std::string_view message) {
        std::lock_guard lock(reportMutex);
        int percentage = static_cast<int>(fraction * 100.0);
        auto now = std::chrono::steady_clock::now();
        if (percentage <= lastPercentage || now - lastReport < kReportInterval) return;
        lastPercentage = percentage;
        lastReport = now;
        tell({{"kind", "report"}, {"percentage", percentage}, {"message", std::string(message)}});
      },
      run.cancel);
  if (outcome.cancelled || run.cancel.requested()) {
    tell({{"kind", "end"}, {"message", "cancelled"}});
    writer_.send(errorMessage(run.id, ErrorCode::RequestCancelled, "the render was cancelled"));
  } else if (outcome.image) {
    tell({{"kind", "end"}, {"message", "wrote " + outcome.image->string()}});
    writer_.send(responseMessage(run.id, {{"image", outcome.image->string()}}));
  } else {
    tell({{"kind", "end"}, {"message", outcome.failure}});
    writer_.send(errorMessage(run.id, ErrorCode::RequestFailed, outcome.failure));
  }
}

bool RenderRuns::cancelRequest(const nlohmann::json& id) {
  std::lock_guard lock(mutex_);
  for (const auto& run : runs_) {
    if (run->id == id && !run->finished) {
      run->cancel.request();
      run->answered.notify_all();
      return true;
    }
  }
  return false;
}

void RenderRuns::cancelProgress(const nlohmann::json& token) {
  std::lock_guard lock(mutex_);
  for (const auto& run : runs_) {
    if (run->token == token) {
      run->cancel.request();
      run->answered.notify_all();
    }
  }
}

bool RenderRuns::responseArrived(const nlohmann::json& id, bool accepted) {
  std::lock_guard lock(mutex_);
  for (const auto& run : runs_) {
    if (!run->createId.is_null() && run->createId == id) {
      {
        std::lock_guard runLock(run->mutex);
        run->tokenAnswered = true;
        run->tokenAccepted = accepted;
      }
      run->answered.notify_all();
      return true;
    }
  }
  return false;
}

void RenderRuns::reapFinished() {
  std::vector<std::shared_ptr<Run>> done;
  {
    std::lock_guard lock(mutex_);
    std::erase_if(runs_, [&](const std::shared_ptr<Run>& run) {
      if (!run->finished) return false;
      done.push_back(run);
      return true;
    });
  }
  for (const auto& run : done) run->thread.join();
}

void RenderRuns::stopAll() {
  std::vector<std::shared_ptr<Run>> all;
  {
    std::lock_guard lock(mutex_);
    all.swap(runs_);
  }
  for (const auto& run : all) {
    run->cancel.request();
    run->answered.notify_all();
  }
  for (const auto& run : all) run->thread.join();
}

}  // namespace sfls
