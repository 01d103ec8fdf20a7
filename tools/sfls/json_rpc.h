// JSON-RPC 2.0 as the Language Server Protocol frames it: each message a
// header ("Content-Length: N", CRLF-terminated lines, a blank line) and N
// bytes of JSON. The reader takes one stream; the writer is shared by every
// thread that answers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "scenefile/read.h"

namespace sfls {

// The error codes of JSON-RPC and of the protocol.
enum class ErrorCode : int {
  ParseError = -32700,
  InvalidRequest = -32600,
  MethodNotFound = -32601,
  InvalidParams = -32602,
  InternalError = -32603,
  ServerNotInitialized = -32002,
  RequestFailed = -32803,
  RequestCancelled = -32800,
  ContentModified = -32801,
};

// The largest message read: a document of the readers' largest size
// (kDefaultMaxFileSize, 1 GiB), JSON-escaped, with room for its escapes
// (a quarter more). A larger one is skipped unread and answered with an
// error, since its text could not be checked anyway.
inline constexpr std::uint64_t kMaxMessageSize =
    scene::kDefaultMaxFileSize + scene::kDefaultMaxFileSize / 4;

// What the reader found next.
struct IncomingMessage {
  enum class Kind {
    Message,    // `json` holds it
    BadJson,    // the body is no JSON; `error` says why
    TooLarge,   // the body was longer than the limit and was skipped
    End,        // the stream ended between messages
    Truncated,  // the stream ended inside a message
    BadHeader,  // the header is unreadable; the stream cannot be resynchronised
  };
  Kind kind = Kind::End;
  nlohmann::json json;
  std::string error;
  std::uint64_t size = 0;  // the body's Content-Length
};

class MessageReader {
 public:
  explicit MessageReader(std::istream& in, std::uint64_t maxSize = kMaxMessageSize)
      : in_(in), maxSize_(maxSize) {}

  // Blocks until a whole message, the end of the stream or a bad header.
  // Memory grows with the bytes that arrive, never with what a header
  // claims. After TooLarge the body is skipped lazily: `skipBody` must be
  // called before the next `next` (so that the error can be answered
  // before the bytes are drained).
  IncomingMessage next();
  // Drains the body of a TooLarge message; false when the stream ended in it.
  bool skipBody(std::uint64_t size);

 private:
  // A header line without its line ending; false at the end of the stream
  // or past the longest line a header may have.
  enum class LineResult { Line, End, TooLong };
  LineResult readHeaderLine(std::string& line);

  std::istream& in_;
  std::uint64_t maxSize_;
};

// Writes whole messages; several threads may send at once.
class MessageWriter {
 public:
  explicit MessageWriter(std::ostream& out) : out_(out) {}

  // Invalid UTF-8 in strings (a document's bytes quoted in a message) is
  // replaced, never a reason to fail. False once the stream has failed.
  bool send(const nlohmann::json& message);

 private:
  std::mutex mutex_;
  std::ostream& out_;
};

// The messages of the protocol's shape.
nlohmann::json responseMessage(const nlohmann::json& id, nlohmann::json result);
nlohmann::json errorMessage(const nlohmann::json& id, ErrorCode code, const std::string& message);
nlohmann::json notificationMessage(const std::string& method, nlohmann::json params);
nlohmann::json requestMessage(const nlohmann::json& id, const std::string& method,
                              nlohmann::json params);

}  // namespace sfls
