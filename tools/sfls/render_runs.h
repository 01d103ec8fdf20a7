// The scenefile.render commands running: each on a thread of its own, its
// progress told with $/progress where the client takes it, cancellable by
// $/cancelRequest or by the progress's cancel button.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <vector>

#include "tools/sfls/json_rpc.h"
#include "tools/sfls/render_command.h"

namespace sfls {

class RenderRuns {
 public:
  explicit RenderRuns(MessageWriter& writer) : writer_(writer) {}
  ~RenderRuns();
  RenderRuns(const RenderRuns&) = delete;
  RenderRuns& operator=(const RenderRuns&) = delete;

  // Starts the render that answers request `id`. `clientToken` is the
  // request's workDoneToken (null for none); `createToken` asks the client
  // for one (window/workDoneProgress/create) where it gave none.
  void start(const nlohmann::json& id, RenderRequest request, const nlohmann::json& clientToken,
             bool createToken);
  // $/cancelRequest: true when `id` is a render still running.
  bool cancelRequest(const nlohmann::json& id);
  // window/workDoneProgress/cancel.
  void cancelProgress(const nlohmann::json& token);
  // A response from the client: true when it answered a token's creation
  // (`accepted`: with a result, not an error).
  bool responseArrived(const nlohmann::json& id, bool accepted);
  // Stops every render (shutdown) and waits for them.
  void stopAll();

 private:
  struct Run;
  void reapFinished();
  void execute(Run& run, const RenderRequest& request);

  MessageWriter& writer_;
  std::mutex mutex_;
  std::vector<std::shared_ptr<Run>> runs_;
  std::uint64_t tokens_ = 0;
};

}  // namespace sfls
