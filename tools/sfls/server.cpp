#include "tools/sfls/server.h"

#include <chrono>
#include <iterator>
#include <thread>

#include "tools/sfls/features.h"
#include "tools/sfls/lsp_diagnostics.h"
#include "tools/sfls/lsp_json.h"
#include "tools/sfls/uri.h"

namespace sfls {
namespace {

constexpr const char* kRenderCommand = "scenefile.render";

// The value at `pointer` of `params`, or `fallback` where it is missing.
bool flagAt(const nlohmann::json& params, const char* pointer) {
  nlohmann::json::json_pointer path(pointer);
  return params.contains(path) && params.at(path) == true;
}

bool isId(const nlohmann::json& id) {
  return id.is_number_integer() || id.is_string();
}

std::string uriOf(const nlohmann::json& params) {
  return params.at("textDocument").at("uri").get<std::string>();
}

}  // namespace

Server::Server(std::istream& in, std::ostream& out, std::ostream& log, ServerOptions options)
    : in_(in),
      log_(log),
      writer_(out),
      options_(std::move(options)),
      renders_(writer_),
      checks_([this](const std::string& uri, std::shared_ptr<Analysis> analysis) {
        post([this, uri, analysis = std::move(analysis)]() mutable {
          checked(uri, std::move(analysis));
        });
      }) {
  // std::cin and std::cerr are tied to std::cout: each read and each log
  // line would flush the output from the reading thread while the handling
  // thread writes to it, and a message would go out twice.
  in_.tie(nullptr);
  log_.tie(nullptr);
}

Server::~Server() = default;

int Server::run() {
  std::thread handler([this] { handleLoop(); });
  readLoop();
  handler.join();
  renders_.stopAll();
  return exitStatus_;
}

void Server::readLoop() {
  MessageReader reader(in_, options_.maxMessageSize);
  for (;;) {
    IncomingMessage message = reader.next();
    switch (message.kind) {
      case IncomingMessage::Kind::Message: {
        // (No copy of the message's values: a client's JSON may nest
        // deeper than a recursive copy has stack for.)
        auto method = message.json.is_object() ? message.json.find("method") : message.json.end();
        bool exit = method != message.json.end() && *method == "exit";
        post([this, json = std::move(message.json)]() mutable { handleMessage(std::move(json)); });
        // Nothing is read after exit: the client may keep the pipe open.
        if (exit) return;
        break;
      }
      case IncomingMessage::Kind::BadJson:
        logLine("sfls: error: a message is not JSON; it was skipped");
        writer_.send(errorMessage(nullptr, ErrorCode::ParseError, message.error));
        break;
      case IncomingMessage::Kind::TooLarge: {
        std::string what = "a message of " + std::to_string(message.size) +
                           " bytes is larger than the limit of " +
                           std::to_string(options_.maxMessageSize) + " bytes; it was skipped";
        logLine("sfls: error: " + what);
        writer_.send(errorMessage(nullptr, ErrorCode::InvalidRequest, what));
        if (!reader.skipBody(message.size)) {
          logLine("sfls: error: the input ended inside a message");
          post([this] { stopHandling(shutdown_ ? 0 : 1); });
          return;
        }
        break;
      }
      case IncomingMessage::Kind::Truncated:
        logLine("sfls: error: the input ended inside a message");
        [[fallthrough]];
      case IncomingMessage::Kind::End:
        post([this] { stopHandling(shutdown_ ? 0 : 1); });
        return;
      case IncomingMessage::Kind::BadHeader:
        // Without a length the next message's start is unknown: no way on.
        logLine("sfls: error: unreadable message header: " + message.error);
        post([this] { stopHandling(1); });
        return;
    }
  }
}

void Server::post(std::function<void()> task) {
  {
    std::lock_guard lock(queueMutex_);
    queue_.push_back(std::move(task));
  }
  queueWake_.notify_one();
}

void Server::handleLoop() {
  while (!stopped_) {
    std::function<void()> task;
    {
      std::unique_lock lock(queueMutex_);
      queueWake_.wait(lock, [this] { return !queue_.empty(); });
      task = std::move(queue_.front());
      queue_.pop_front();
    }
    try {
      task();
    } catch (const std::exception& error) {
      logLine(std::string("sfls: error: ") + error.what());
    }
  }
}

void Server::stopHandling(int status) {
  stopped_ = true;
  exitStatus_ = status;
}

void Server::logLine(const std::string& line) {
  std::lock_guard lock(logMutex_);
  log_ << line << '\n' << std::flush;
}

void Server::handleMessage(nlohmann::json message) {
  if (!options_.verbose) {
    dispatch(std::move(message));
    return;
  }
  auto found = message.is_object() ? message.find("method") : message.end();
  std::string method =
      found != message.end() && found->is_string() ? found->get<std::string>() : "?";
  auto start = std::chrono::steady_clock::now();
  dispatch(std::move(message));
  std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  logLine("sfls: " + method + ": " + std::to_string(took.count()) + " ms");
}

void Server::dispatch(nlohmann::json message) {
  if (!message.is_object()) {
    writer_.send(errorMessage(nullptr, ErrorCode::InvalidRequest, "a message is a JSON object"));
    return;
  }
  auto method = message.find("method");
  auto id = message.find("id");
  if (method == message.end()) {
    if (id != message.end() && (message.contains("result") || message.contains("error"))) {
      handleResponse(message);
    } else {
      writer_.send(errorMessage(id != message.end() && isId(*id) ? *id : nlohmann::json(),
                                ErrorCode::InvalidRequest, "the message has no method"));
    }
    return;
  }
  if (!method->is_string() || (id != message.end() && !isId(*id))) {
    writer_.send(errorMessage(nullptr, ErrorCode::InvalidRequest,
                              "a method is a string, an id a number or a string"));
    return;
  }
  static const nlohmann::json kNoParams = nlohmann::json::object();
  auto params = message.find("params");
  const nlohmann::json& given = params != message.end() ? *params : kNoParams;
  const std::string& name = method->get_ref<const std::string&>();
  // exit ends the server even when sent with an id: the reading thread
  // stops at it whatever its shape, and nothing would come after it.
  if (id == message.end() || name == "exit") {
    try {
      handleNotification(name, given);
    } catch (const std::exception& error) {
      logLine("sfls: error: " + name + ": " + error.what());
    }
    return;
  }
  try {
    handleRequest(*id, name, given);
  } catch (const nlohmann::json::exception& error) {
    writer_.send(errorMessage(*id, ErrorCode::InvalidParams, error.what()));
  } catch (const std::exception& error) {
    writer_.send(errorMessage(*id, ErrorCode::InternalError, error.what()));
  }
}

void Server::handleRequest(const nlohmann::json& id, const std::string& method,
                           const nlohmann::json& params) {
  if (!initialized_) {
    if (method != "initialize") {
      writer_.send(
          errorMessage(id, ErrorCode::ServerNotInitialized, "the server is not initialized"));
      return;
    }
    nlohmann::json result = initializeResult(params);
    initialized_ = true;
    writer_.send(responseMessage(id, std::move(result)));
    return;
  }
  if (shutdown_) {
    writer_.send(errorMessage(id, ErrorCode::InvalidRequest, "the server is shut down"));
    return;
  }
  if (method == "initialize") {
    writer_.send(errorMessage(id, ErrorCode::InvalidRequest, "the server is already initialized"));
  } else if (method == "shutdown") {
    shutdown_ = true;
    renders_.stopAll();
    // Every request is answered: those still waiting for a check will not be.
    for (const WaitingRequest& request : waiting_) {
      writer_.send(errorMessage(request.id, ErrorCode::RequestCancelled, "the server shut down"));
    }
    waiting_.clear();
    writer_.send(responseMessage(id, nullptr));
  } else if (method == "workspace/executeCommand") {
    handleExecuteCommand(id, params);
  } else if (!handleFeature(id, method, params)) {
    writer_.send(errorMessage(id, ErrorCode::MethodNotFound, "unknown method " + method));
  }
}

void Server::handleNotification(const std::string& method, const nlohmann::json& params) {
  if (method == "exit") {
    stopHandling(shutdown_ ? 0 : 1);
    return;
  }
  // Before initialize, notifications are dropped (exit aside).
  if (!initialized_) return;
  if (method == "textDocument/didOpen") {
    didOpen(params);
  } else if (method == "textDocument/didChange") {
    didChange(params);
  } else if (method == "textDocument/didClose") {
    didClose(params);
  } else if (method == "$/cancelRequest") {
    cancelRequest(params);
  } else if (method == "window/workDoneProgress/cancel") {
    renders_.cancelProgress(params.at("token"));
  } else if (method != "initialized" && method != "textDocument/didSave" &&
             method.rfind("$/", 0) != 0) {
    // didSave needs nothing: the check reads the editor's text, not the file.
    logLine("sfls: ignored the notification " + method);
  }
}

void Server::handleResponse(const nlohmann::json& message) {
  renders_.responseArrived(message.at("id"), !message.contains("error"));
}

nlohmann::json Server::initializeResult(const nlohmann::json& params) {
  snippets_ = flagAt(params, "/capabilities/textDocument/completion/completionItem/snippetSupport");
  workDoneProgress_ = flagAt(params, "/capabilities/window/workDoneProgress");
  nlohmann::json capabilities = {
      // Positions count UTF-16 units, the protocol's default and the one
      // encoding every client has.
      {"positionEncoding", "utf-16"},
      {"textDocumentSync",
       {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
      {"hoverProvider", true},
      // A space after START OBJECT asks for the object kinds.
      {"completionProvider", {{"triggerCharacters", {" "}}, {"resolveProvider", false}}},
      {"documentSymbolProvider", true},
      {"foldingRangeProvider", true},
      {"documentFormattingProvider", true},
      {"documentRangeFormattingProvider", true},
      {"codeActionProvider", {{"codeActionKinds", {"quickfix", "source.fixAll"}}}},
      {"executeCommandProvider", {{"commands", {kRenderCommand}}}},
  };
  return {{"capabilities", std::move(capabilities)},
          {"serverInfo", {{"name", "sfls"}, {"version", SCENEFILE_VERSION}}}};
}

bool Server::handleFeature(const nlohmann::json& id, const std::string& method,
                           const nlohmann::json& params) {
  static const char* const kMethods[] = {
      "textDocument/hover",        "textDocument/completion", "textDocument/documentSymbol",
      "textDocument/foldingRange", "textDocument/formatting", "textDocument/rangeFormatting",
      "textDocument/codeAction"};
  if (std::find(std::begin(kMethods), std::end(kMethods), method) == std::end(kMethods))
    return false;
  const Document* open = document(params);
  if (open == nullptr) {
    writer_.send(
        errorMessage(id, ErrorCode::InvalidParams, "the document is not open: " + uriOf(params)));
    return true;
  }
  // Hover and completion answer at once, from the text where the check of
  // this version is still running; the others need that check.
  if (method == "textDocument/hover") {
    writer_.send(responseMessage(
        id, hover(*open, currentAnalysis(*open), params.at("position").get<LspPosition>())));
  } else if (method == "textDocument/completion") {
    writer_.send(
        responseMessage(id, completion(*open, currentAnalysis(*open),
                                       params.at("position").get<LspPosition>(), snippets_)));
  } else if (method == "textDocument/documentSymbol") {
    answerWhenChecked(
        id, open->uri(), [](const Document& d, const Analysis& a) { return documentSymbols(d, a); },
        true);
  } else if (method == "textDocument/foldingRange") {
    answerWhenChecked(
        id, open->uri(), [](const Document& d, const Analysis& a) { return foldingRanges(d, a); },
        true);
  } else if (method == "textDocument/formatting") {
    answerWhenChecked(id, open->uri(), [](const Document& d, const Analysis& a) {
      return formattingEdits(d, a, std::nullopt);
    });
  } else if (method == "textDocument/rangeFormatting") {
    auto range = params.at("range").get<LspRange>();
    answerWhenChecked(id, open->uri(), [range](const Document& d, const Analysis& a) {
      return formattingEdits(d, a, range);
    });
  } else {
    CodeActionQuery query = CodeActionQuery::fromParams(params);
    answerWhenChecked(id, open->uri(), [this, query](const Document& d, const Analysis& a) {
      return codeActions(d, a, query, options_.diagnosticsDocUri);
    });
  }
  return true;
}

void Server::handleExecuteCommand(const nlohmann::json& id, const nlohmann::json& params) {
  std::string command = params.at("command").get<std::string>();
  if (command != kRenderCommand) {
    writer_.send(errorMessage(id, ErrorCode::InvalidParams, "unknown command " + command));
    return;
  }
  // Arguments: the document's URI, then sfrender's settings by name, each a
  // number, a string or a boolean (so that nothing deeper is copied).
  static const nlohmann::json kNone = nlohmann::json::array();
  auto found = params.find("arguments");
  const nlohmann::json& arguments = found != params.end() ? *found : kNone;
  auto flat = [](const nlohmann::json& settings) {
    return settings.is_null() ||
           (settings.is_object() &&
            std::all_of(settings.begin(), settings.end(),
                        [](const nlohmann::json& value) { return value.is_primitive(); }));
  };
  if (!arguments.is_array() || arguments.empty() || arguments.size() > 2 ||
      !arguments[0].is_string() || (arguments.size() == 2 && !flat(arguments[1]))) {
    writer_.send(errorMessage(id, ErrorCode::InvalidParams,
                              "scenefile.render takes the document's URI, then an object of "
                              "its settings"));
    return;
  }
  std::string uri = arguments[0].get<std::string>();
  auto open = documents_.find(uri);
  if (open == documents_.end()) {
    writer_.send(errorMessage(id, ErrorCode::InvalidParams, "the document is not open: " + uri));
    return;
  }
  std::optional<std::filesystem::path> file = pathOfUri(uri);
  if (!file) {
    writer_.send(errorMessage(id, ErrorCode::RequestFailed,
                              "the document has no file to render beside: " + uri));
    return;
  }
  RenderRequest request;
  request.file = *file;
  request.arguments = arguments.size() > 1 ? arguments[1] : nlohmann::json();
  request.text = open->second.text();
  auto token = params.find("workDoneToken");
  bool hasToken = token != params.end() && isId(*token);
  renders_.start(id, std::move(request), hasToken ? *token : nlohmann::json(), workDoneProgress_);
}

void Server::didOpen(const nlohmann::json& params) {
  const nlohmann::json& item = params.at("textDocument");
  std::string uri = item.at("uri").get<std::string>();
  // The text is moved out of the message, never copied: it may be 100 MB.
  auto& text = const_cast<nlohmann::json&>(item.at("text")).get_ref<std::string&>();
  Document opened(uri, item.at("version").get<std::int64_t>(), std::move(text));
  analyses_.erase(uri);
  staleOutlines_.erase(uri);
  auto [place, inserted] = documents_.insert_or_assign(uri, std::move(opened));
  scheduleCheck(place->second);
}

void Server::didChange(const nlohmann::json& params) {
  std::string uri = uriOf(params);
  auto open = documents_.find(uri);
  if (open == documents_.end()) {
    logLine("sfls: error: a change to a document that is not open: " + uri);
    return;
  }
  Document& changed = open->second;
  // Neither the check waiting for the old version nor the last one's
  // analysis will be wanted: dropped first, they no longer share the text,
  // which is then edited in place.
  checks_.forget(uri);
  dropAnalysis(uri);
  for (const nlohmann::json& change : params.at("contentChanges")) {
    std::optional<LspRange> range;
    if (auto found = change.find("range"); found != change.end()) range = found->get<LspRange>();
    changed.applyChange(range, change.at("text").get_ref<const std::string&>());
  }
  changed.setVersion(params.at("textDocument").at("version").get<std::int64_t>());
  scheduleCheck(changed);
}

void Server::didClose(const nlohmann::json& params) {
  std::string uri = uriOf(params);
  checks_.close(uri);
  analyses_.erase(uri);
  staleOutlines_.erase(uri);
  if (documents_.erase(uri) == 0) return;
  std::erase_if(waiting_, [&](const WaitingRequest& request) {
    if (request.uri != uri) return false;
    writer_.send(errorMessage(request.id, ErrorCode::ContentModified, "the document was closed"));
    return true;
  });
  // A closed document keeps no diagnostics in the editor.
  writer_.send(notificationMessage("textDocument/publishDiagnostics",
                                   {{"uri", uri}, {"diagnostics", nlohmann::json::array()}}));
}

void Server::cancelRequest(const nlohmann::json& params) {
  const nlohmann::json& id = params.at("id");
  auto waiting = std::find_if(waiting_.begin(), waiting_.end(),
                              [&](const WaitingRequest& request) { return request.id == id; });
  if (waiting != waiting_.end()) {
    writer_.send(errorMessage(id, ErrorCode::RequestCancelled, "the request was cancelled"));
    waiting_.erase(waiting);
    return;
  }
  // A render answers its cancellation itself; any other request was answered already.
  renders_.cancelRequest(id);
}

void Server::scheduleCheck(const Document& document) {
  CheckJob job;
  job.uri = document.uri();
  job.version = document.version();
  job.text = document.sharedText();
  job.file = pathOfUri(document.uri()).value_or(std::filesystem::path());
  checks_.schedule(std::move(job));
}

void Server::checked(const std::string& uri, std::shared_ptr<Analysis> analysis) {
  auto open = documents_.find(uri);
  // The check of a version the document has left behind is never shown.
  if (open == documents_.end() || open->second.version() != analysis->version ||
      open->second.sharedText() != analysis->text) {
    return;
  }
  const Document& document = open->second;
  if (options_.verbose) {
    logLine("sfls: checked " + uri + " version " + std::to_string(analysis->version) + " in " +
            std::to_string(analysis->seconds * 1000) + " ms");
  }
  writer_.send(notificationMessage(
      "textDocument/publishDiagnostics",
      publishDiagnosticsParams(document, *analysis, options_.diagnosticsDocUri)));
  analyses_[uri] = analysis;
  staleOutlines_.erase(uri);
  std::vector<WaitingRequest> ready;
  std::erase_if(waiting_, [&](WaitingRequest& request) {
    if (request.uri != uri) return false;
    ready.push_back(std::move(request));
    return true;
  });
  for (const WaitingRequest& request : ready) {
    try {
      writer_.send(responseMessage(request.id, request.answer(document, *analysis)));
    } catch (const std::exception& error) {
      writer_.send(errorMessage(request.id, ErrorCode::InternalError, error.what()));
    }
  }
}

void Server::dropAnalysis(const std::string& uri) {
  auto found = analyses_.find(uri);
  if (found == analyses_.end()) return;
  // The last check is of an older text: its scene is dropped now rather
  // than when the new one is done, so that two never share the memory, and
  // the text, no longer shared, is edited in place. Its outline stays.
  auto outline = std::make_shared<Analysis>();
  outline->version = found->second->version;
  outline->format = found->second->format;
  outline->outline = std::move(found->second->outline);
  staleOutlines_[uri] = {std::move(outline), documents_.at(uri).lineCount()};
  found->second->text.reset();
  checks_.release(std::move(found->second));
  analyses_.erase(found);
}

void Server::answerWhenChecked(const nlohmann::json& id, const std::string& uri,
                               AnalysisAnswer answer, bool outlineWillDo) {
  const Document& open = documents_.at(uri);
  auto stale = staleOutlines_.find(uri);
  if (const Analysis* analysis = currentAnalysis(open)) {
    writer_.send(responseMessage(id, answer(open, *analysis)));
  } else if (outlineWillDo && stale != staleOutlines_.end() &&
             stale->second.lineCount == open.lineCount()) {
    writer_.send(responseMessage(id, answer(open, *stale->second.analysis)));
  } else {
    waiting_.push_back({id, uri, std::move(answer)});
  }
}

const Document* Server::document(const nlohmann::json& params) const {
  auto open = documents_.find(uriOf(params));
  return open == documents_.end() ? nullptr : &open->second;
}

const Analysis* Server::currentAnalysis(const Document& document) const {
  auto found = analyses_.find(document.uri());
  if (found == analyses_.end() || found->second->version != document.version() ||
      found->second->text != document.sharedText()) {
    return nullptr;
  }
  return found->second.get();
}

}  // namespace sfls
