#include "tools/sfls/server.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <sstream>
#include <streambuf>
#include <thread>
#include <vector>

namespace sfls {
namespace {

std::string framed(nlohmann::json message) {
  message["jsonrpc"] = "2.0";
  std::string body = message.dump();
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

// A stream between two threads, as a pipe is: reads wait for writes, and
// end when the writing side closes.
class Channel : public std::streambuf {
 public:
  void write(const std::string& bytes) {
    std::lock_guard lock(mutex_);
    pending_ += bytes;
    changed_.notify_all();
  }
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    changed_.notify_all();
  }
  std::string written() {
    std::lock_guard lock(mutex_);
    return written_;
  }
  // Waits until what was written holds `text`; false after 10 s.
  bool waitFor(const std::string& text) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(10),
                             [&] { return written_.find(text) != std::string::npos; });
  }

 protected:
  int_type underflow() override {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !pending_.empty() || closed_; });
    if (pending_.empty()) return traits_type::eof();
    current_ = std::move(pending_);
    pending_.clear();
    setg(current_.data(), current_.data(), current_.data() + current_.size());
    return traits_type::to_int_type(current_[0]);
  }
  std::streamsize xsputn(const char* bytes, std::streamsize count) override {
    std::lock_guard lock(mutex_);
    written_.append(bytes, static_cast<std::size_t>(count));
    changed_.notify_all();
    return count;
  }
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) {
      char byte = traits_type::to_char_type(c);
      xsputn(&byte, 1);
    }
    return c;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::string pending_, current_, written_;
  bool closed_ = false;
};

struct Session {
  int status = -1;
  std::vector<nlohmann::json> messages;
  std::string log;

  // The first message with `id`, or null.
  nlohmann::json response(const nlohmann::json& id) const {
    for (const auto& message : messages) {
      if (message.contains("id") && message["id"] == id && !message.contains("method"))
        return message;
    }
    return nullptr;
  }
  std::vector<nlohmann::json> notifications(const std::string& method) const {
    std::vector<nlohmann::json> found;
    for (const auto& message : messages) {
      if (message.value("method", "") == method) found.push_back(message);
    }
    return found;
  }
};

Session serve(const std::vector<nlohmann::json>& messages, std::string tail = {}) {
  std::string input;
  for (const auto& message : messages) input += framed(message);
  std::istringstream in(input + tail);
  std::ostringstream out;
  std::ostringstream log;
  Session session;
  session.status = Server(in, out, log, ServerOptions{"file:///doc"}).run();
  std::istringstream written(out.str());
  MessageReader reader(written);
  for (IncomingMessage m = reader.next(); m.kind == IncomingMessage::Kind::Message;
       m = reader.next()) {
    session.messages.push_back(m.json);
  }
  session.log = log.str();
  return session;
}

const nlohmann::json kInitialize = {
    {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", nlohmann::json::object()}}}};
const nlohmann::json kShutdown = {{"id", "end"}, {"method", "shutdown"}};
const nlohmann::json kExit = {{"method", "exit"}};

nlohmann::json didOpen(const std::string& uri, const std::string& text) {
  return {{"method", "textDocument/didOpen"},
          {"params",
           {{"textDocument",
             {{"uri", uri}, {"languageId", "scenefile"}, {"version", 1}, {"text", text}}}}}};
}

const std::string kTypo =
    "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 8\n0 0 0 1\n"
    "LIGHT\n1 1 1\n1 0 0 5\n0 1 0 5\n0 0 1 5\n0 0 0 1\n"
    "SPHRE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";

TEST(Server, AnswersTheLifecycle) {
  Session session = serve({kInitialize, kShutdown, kExit});
  EXPECT_EQ(session.status, 0);
  nlohmann::json result = session.response(1)["result"];
  EXPECT_EQ(result["capabilities"]["textDocumentSync"]["change"], 2);
  EXPECT_EQ(result["serverInfo"]["name"], "sfls");
  EXPECT_TRUE(session.response("end")["result"].is_null());
}

TEST(Server, EndsAtExitSentAsARequest) {
  nlohmann::json exitRequest = {{"id", 5}, {"method", "exit"}};
  EXPECT_EQ(serve({kInitialize, kShutdown, exitRequest}).status, 0);
}

TEST(Server, CancelsARequestThatWaitsForItsCheck) {
  std::string uri = "file:///nowhere/large.sf";
  std::string large = kTypo;
  for (int i = 0; i < 300'000; ++i) large += "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  nlohmann::json symbols = {{"id", 2},
                            {"method", "textDocument/documentSymbol"},
                            {"params", {{"textDocument", {{"uri", uri}}}}}};
  nlohmann::json cancel = {{"method", "$/cancelRequest"}, {"params", {{"id", 2}}}};
  Session session = serve({kInitialize, didOpen(uri, large), symbols, cancel, kShutdown, kExit});
  EXPECT_EQ(session.response(2)["error"]["code"], -32800);
}

TEST(Server, AnswersTheRequestsThatWaitAtShutdown) {
  std::string uri = "file:///nowhere/large.sf";
  std::string large = kTypo;
  for (int i = 0; i < 300'000; ++i) large += "SPHERE\n1 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  nlohmann::json folding = {{"id", 2},
                            {"method", "textDocument/foldingRange"},
                            {"params", {{"textDocument", {{"uri", uri}}}}}};
  Session session = serve({kInitialize, didOpen(uri, large), folding, kShutdown, kExit});
  EXPECT_EQ(session.response(2)["error"]["code"], -32800);
  EXPECT_EQ(session.status, 0);
}

// A message's JSON nested a million deep, where a method, an id, a code
// action's kinds and the render's settings belong: each refused or
// ignored, never copied or printed by recursion, which would run out of
// stack.
TEST(Server, TakesJsonNestedAMillionDeep) {
  std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  std::string uri = "file:///nowhere/typo.sf";
  auto message = [](const std::string& json) {
    return "Content-Length: " + std::to_string(json.size()) + "\r\n\r\n" + json;
  };
  std::string range =
      R"("range":{"start":{"line":0,"character":0},"end":{"line":0,"character":0}})";
  std::string input =
      framed(kInitialize) + framed(didOpen(uri, kTypo)) +
      message(R"({"jsonrpc":"2.0","method":)" + deep + "}") +
      message(R"({"jsonrpc":"2.0","id":)" + deep + R"(,"method":"shutdown"})") +
      message(
          R"({"jsonrpc":"2.0","id":2,"method":"textDocument/codeAction","params":{"textDocument":{"uri":")" +
          uri + R"("},)" + range + R"(,"context":{"diagnostics":[],"only":)" + deep + "}}}") +
      message(
          R"({"jsonrpc":"2.0","id":3,"method":"workspace/executeCommand","params":{"command":"scenefile.render","arguments":[")" +
          uri + R"(",{"width":)" + deep + "}]}}") +
      message(R"({"jsonrpc":"2.0","method":"$/cancelRequest","params":{"id":)" + deep + "}}") +
      framed(kShutdown) + framed(kExit);
  std::istringstream in(input);
  std::ostringstream out, log;
  EXPECT_EQ(Server(in, out, log, ServerOptions{}).run(), 0);
  EXPECT_NE(out.str().find(R"("id":3)"), std::string::npos);
  EXPECT_NE(out.str().find(R"("id":"end")"), std::string::npos);
}

TEST(Server, EndsWithOneWithoutShutdown) {
  EXPECT_EQ(serve({kInitialize, kExit}).status, 1);
  // The input ending is no exit either.
  EXPECT_EQ(serve({kInitialize}).status, 1);
  EXPECT_EQ(serve({kInitialize, kShutdown}).status, 0);
}

TEST(Server, RefusesRequestsOutsideItsLife) {
  nlohmann::json early = {{"id", 7}, {"method", "shutdown"}};
  nlohmann::json late = {
      {"id", 8}, {"method", "textDocument/hover"}, {"params", nlohmann::json::object()}};
  Session session = serve({early, kInitialize, kShutdown, late, kExit});
  EXPECT_EQ(session.response(7)["error"]["code"], -32002);
  EXPECT_EQ(session.response(8)["error"]["code"], -32600);
  EXPECT_EQ(session.status, 0);
}

TEST(Server, AnswersUnknownMethodsAndBadMessages) {
  nlohmann::json unknown = {{"id", 2}, {"method", "no/such"}};
  nlohmann::json noParams = {{"id", 3}, {"method", "textDocument/hover"}};
  nlohmann::json notification = {{"method", "no/such"}};
  Session session = serve({kInitialize, unknown, noParams, notification, kShutdown, kExit},
                          "Content-Length: 2\r\n\r\n{");
  EXPECT_EQ(session.response(2)["error"]["code"], -32601);
  EXPECT_EQ(session.response(3)["error"]["code"], -32602);
  EXPECT_EQ(session.status, 0);
}

TEST(Server, GoesOnAfterBadJson) {
  std::string input =
      framed(kInitialize) + "Content-Length: 1\r\n\r\n{" + framed(kShutdown) + framed(kExit);
  std::istringstream in(input);
  std::ostringstream out, log;
  int status = Server(in, out, log, ServerOptions{}).run();
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.str().find("-32700"), std::string::npos);
  EXPECT_NE(out.str().find("\"id\":\"end\""), std::string::npos);
}

TEST(Server, PublishesSfchecksDiagnosticsAndTheirFixes) {
  std::string uri = "file:///nowhere/typo.sf";
  nlohmann::json actions = {
      {"id", 2},
      {"method", "textDocument/codeAction"},
      {"params",
       {{"textDocument", {{"uri", uri}}},
        {"range",
         {{"start", {{"line", 12}, {"character", 2}}}, {"end", {{"line", 12}, {"character", 2}}}}},
        {"context", {{"diagnostics", nlohmann::json::array()}}}}}};
  Channel input, output;
  std::istream in(&input);
  std::ostream out(&output);
  std::ostringstream log;
  Server server(in, out, log, ServerOptions{"file:///doc"});
  int status = -1;
  std::thread serving([&] { status = server.run(); });
  // The code action waits for the document's check, then is answered.
  input.write(framed(kInitialize) + framed(didOpen(uri, kTypo)) + framed(actions));
  EXPECT_TRUE(output.waitFor("\"id\":2"));
  input.write(framed(kShutdown) + framed(kExit));
  serving.join();
  EXPECT_EQ(status, 0);
  Session session;
  {
    std::istringstream written(output.written());
    MessageReader reader(written);
    for (IncomingMessage m = reader.next(); m.kind == IncomingMessage::Kind::Message;
         m = reader.next()) {
      session.messages.push_back(m.json);
    }
  }
  auto published = session.notifications("textDocument/publishDiagnostics");
  ASSERT_EQ(published.size(), 1u);
  nlohmann::json diagnostic = published[0]["params"]["diagnostics"][0];
  EXPECT_EQ(diagnostic["code"], "unknown-keyword");
  EXPECT_EQ(diagnostic["range"]["start"], (nlohmann::json{{"line", 12}, {"character", 0}}));
  EXPECT_EQ(diagnostic["range"]["end"], (nlohmann::json{{"line", 12}, {"character", 5}}));
  EXPECT_EQ(diagnostic["codeDescription"]["href"], "file:///doc#unknown-keyword");
  EXPECT_NE(diagnostic["message"].get<std::string>().find("\nhint: did you mean 'SPHERE'?"),
            std::string::npos);
  nlohmann::json action = session.response(2)["result"][0];
  EXPECT_EQ(action["kind"], "quickfix");
  EXPECT_EQ(action["edit"]["changes"][uri][0]["newText"], "SPHERE");
}

TEST(Server, RefusesAMessageOverTheLimitAndGoesOn) {
  std::string input = framed(kInitialize) + "Content-Length: 5000\r\n\r\n" +
                      std::string(5000, ' ') + framed(kShutdown) + framed(kExit);
  std::istringstream in(input);
  std::ostringstream out, log;
  ServerOptions options;
  options.maxMessageSize = 1000;
  EXPECT_EQ(Server(in, out, log, options).run(), 0);
  EXPECT_NE(out.str().find("-32600"), std::string::npos);
  EXPECT_NE(log.str().find("larger than the limit of 1000 bytes"), std::string::npos);
}

TEST(Server, EndsOnAnUnreadableHeader) {
  std::istringstream in(framed(kInitialize) + "Content-Length: -1\r\n\r\n" + framed(kShutdown));
  std::ostringstream out, log;
  EXPECT_EQ(Server(in, out, log, ServerOptions{}).run(), 1);
  EXPECT_NE(log.str().find("unreadable message header"), std::string::npos);
  EXPECT_EQ(out.str().find("\"id\":\"end\""), std::string::npos);
}

}  // namespace
}  // namespace sfls
