// The language server: reads messages on the caller's thread, handles them
// in order on a thread of its own, checks documents on a third
// (CheckWorker) and renders on more (RenderRuns), so that no check or
// render delays an answer. Lifecycle and errors as LSP 3.17 says
// (docs/TOOLS.md, "sfls").
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <istream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "tools/sfls/analysis.h"
#include "tools/sfls/check_worker.h"
#include "tools/sfls/document.h"
#include "tools/sfls/json_rpc.h"
#include "tools/sfls/render_runs.h"

namespace sfls {

struct ServerOptions {
  // codeDescription.href of every diagnostic (diagnosticsDocUri()).
  std::string diagnosticsDocUri;
  // The largest message read (json_rpc.h).
  std::uint64_t maxMessageSize = kMaxMessageSize;
  // --verbose: how long each message and each check took, on the log.
  bool verbose = false;
};

class Server {
 public:
  Server(std::istream& in, std::ostream& out, std::ostream& log, ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Serves until `exit` or the end of the input. Returns the exit status:
  // 0 after shutdown, 1 without it or after a header that cannot be read.
  int run();

 private:
  // A request that needs the check of its document's current version,
  // answered once that check is done.
  using AnalysisAnswer = std::function<nlohmann::json(const Document&, const Analysis&)>;
  struct WaitingRequest {
    nlohmann::json id;
    std::string uri;
    AnalysisAnswer answer;
  };

  // The handling thread's queue: messages, finished checks, the end.
  void post(std::function<void()> task);
  void handleLoop();
  void readLoop();

  void handleMessage(nlohmann::json message);
  void dispatch(nlohmann::json message);
  void handleRequest(const nlohmann::json& id, const std::string& method,
                     const nlohmann::json& params);
  void handleNotification(const std::string& method, const nlohmann::json& params);
  void handleResponse(const nlohmann::json& message);
  nlohmann::json initializeResult(const nlohmann::json& params);
  // A request that a feature answers; false for an unknown method.
  bool handleFeature(const nlohmann::json& id, const std::string& method,
                     const nlohmann::json& params);
  void handleExecuteCommand(const nlohmann::json& id, const nlohmann::json& params);

  void didOpen(const nlohmann::json& params);
  void didChange(const nlohmann::json& params);
  void didClose(const nlohmann::json& params);
  void cancelRequest(const nlohmann::json& params);
  void scheduleCheck(const Document& document);
  void checked(const std::string& uri, std::shared_ptr<Analysis> analysis);
  // Answers now where the current version's check is done, else when it
  // is; with `outlineWillDo`, now from the last check's outline where the
  // document still has as many lines as then (symbols, folding).
  void answerWhenChecked(const nlohmann::json& id, const std::string& uri, AnalysisAnswer answer,
                         bool outlineWillDo = false);
  void dropAnalysis(const std::string& uri);

  const Document* document(const nlohmann::json& params) const;
  // The check of `document`'s current version, or nullptr while it runs.
  const Analysis* currentAnalysis(const Document& document) const;
  void logLine(const std::string& line);
  void stopHandling(int status);

  std::istream& in_;
  std::ostream& log_;
  std::mutex logMutex_;
  MessageWriter writer_;
  ServerOptions options_;

  std::mutex queueMutex_;
  std::condition_variable queueWake_;
  std::deque<std::function<void()>> queue_;

  // The handling thread's own state.
  bool initialized_ = false;
  bool shutdown_ = false;
  bool stopped_ = false;
  int exitStatus_ = 1;
  bool snippets_ = false;
  bool workDoneProgress_ = false;
  std::map<std::string, Document> documents_;
  std::map<std::string, std::shared_ptr<Analysis>> analyses_;
  // The outline of a document's last check, kept (its scene dropped) once
  // the document has changed, with the number of lines it had then: an
  // outline of a text with as many lines is near enough for symbols and
  // folding while the new check runs, as clangd serves a stale AST.
  struct StaleOutline {
    std::shared_ptr<const Analysis> analysis;
    std::uint32_t lineCount = 0;
  };
  std::map<std::string, StaleOutline> staleOutlines_;
  std::vector<WaitingRequest> waiting_;

  // Last, so that they stop first: their threads post to the queue above.
  RenderRuns renders_;
  CheckWorker checks_;
};

}  // namespace sfls
