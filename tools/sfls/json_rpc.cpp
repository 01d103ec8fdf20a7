#include "tools/sfls/json_rpc.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace sfls {
namespace {

// No header line of the protocol comes near this; a longer one is no header.
constexpr std::size_t kMaxHeaderLine = 1024;
constexpr std::size_t kMaxHeaderLines = 32;
// The body arrives in chunks of this size, so that a Content-Length that the
// bytes do not follow costs no memory.
constexpr std::size_t kChunk = std::size_t{1} << 20;

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

IncomingMessage badHeader(std::string error) {
  IncomingMessage message;
  message.kind = IncomingMessage::Kind::BadHeader;
  message.error = std::move(error);
  return message;
}

}  // namespace

MessageReader::LineResult MessageReader::readHeaderLine(std::string& line) {
  line.clear();
  std::streambuf& buffer = *in_.rdbuf();
  for (;;) {
    int c = buffer.sbumpc();
    if (c == std::char_traits<char>::eof()) return LineResult::End;
    if (c == '\n') break;
    if (line.size() == kMaxHeaderLine) return LineResult::TooLong;
    line.push_back(static_cast<char>(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return LineResult::Line;
}

IncomingMessage MessageReader::next() {
  std::optional<std::uint64_t> length;
  std::string line;
  for (std::size_t lines = 0;; ++lines) {
    LineResult result = readHeaderLine(line);
    if (result == LineResult::End) {
      IncomingMessage end;
      end.kind = lines == 0 && line.empty() ? IncomingMessage::Kind::End
                                            : IncomingMessage::Kind::Truncated;
      return end;
    }
    if (result == LineResult::TooLong) return badHeader("a header line is too long");
    if (line.empty()) break;
    if (lines == kMaxHeaderLines) return badHeader("the header has too many lines");
    std::size_t colon = line.find(':');
    if (colon == std::string::npos) return badHeader("a header line has no ':'");
    std::string_view name = trimmed(std::string_view(line).substr(0, colon));
    std::string_view value = trimmed(std::string_view(line).substr(colon + 1));
    // Content-Type and any other header say nothing the reader needs.
    if (!equalsIgnoringCase(name, "Content-Length")) continue;
    std::uint64_t number = 0;
    auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
    if (error != std::errc{} || end != value.data() + value.size() || value.empty()) {
      return badHeader("Content-Length is not a number of bytes");
    }
    length = number;
  }
  if (!length) return badHeader("the header has no Content-Length");

  IncomingMessage message;
  message.size = *length;
  if (*length > maxSize_) {
    message.kind = IncomingMessage::Kind::TooLarge;
    return message;
  }
  std::string body;
  std::streambuf& buffer = *in_.rdbuf();
  while (body.size() < *length) {
    std::size_t want = std::min<std::uint64_t>(kChunk, *length - body.size());
    std::size_t had = body.size();
    body.resize(had + want);
    auto got = static_cast<std::size_t>(
        buffer.sgetn(body.data() + had, static_cast<std::streamsize>(want)));
    body.resize(had + got);
    if (got < want) {
      message.kind = IncomingMessage::Kind::Truncated;
      return message;
    }
  }
  message.json = nlohmann::json::parse(body, nullptr, false);
  if (message.json.is_discarded()) {
    message.json = nullptr;
    message.kind = IncomingMessage::Kind::BadJson;
    message.error = "the message is not JSON";
    return message;
  }
  message.kind = IncomingMessage::Kind::Message;
  return message;
}

bool MessageReader::skipBody(std::uint64_t size) {
  std::string chunk(kChunk, '\0');
  std::streambuf& buffer = *in_.rdbuf();
  while (size > 0) {
    auto want = static_cast<std::streamsize>(std::min<std::uint64_t>(kChunk, size));
    std::streamsize got = buffer.sgetn(chunk.data(), want);
    if (got < want) return false;
    size -= static_cast<std::uint64_t>(got);
  }
  return true;
}

bool MessageWriter::send(const nlohmann::json& message) {
  std::string body = message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard lock(mutex_);
  out_ << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out_.flush();
  return static_cast<bool>(out_);
}

nlohmann::json responseMessage(const nlohmann::json& id, nlohmann::json result) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
}

nlohmann::json errorMessage(const nlohmann::json& id, ErrorCode code, const std::string& message) {
  return {{"jsonrpc", "2.0"},
          {"id", id},
          {"error", {{"code", static_cast<int>(code)}, {"message", message}}}};
}

nlohmann::json notificationMessage(const std::string& method, nlohmann::json params) {
  return {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
}

nlohmann::json requestMessage(const nlohmann::json& id, const std::string& method,
                              nlohmann::json params) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}};
}

}  // namespace sfls
