#include "tools/sfls/json_rpc.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace sfls {
namespace {

using Kind = IncomingMessage::Kind;

std::string framed(const std::string& body) {
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

TEST(MessageReader, ReadsFramedMessagesWithAnyHeaderCase) {
  std::istringstream in(framed(R"({"a":1})") +
                        "content-length: 7\r\nContent-Type: application/vscode-jsonrpc; "
                        "charset=utf-8\r\n\r\n{\"b\":2}");
  MessageReader reader(in);
  IncomingMessage first = reader.next();
  ASSERT_EQ(first.kind, Kind::Message);
  EXPECT_EQ(first.json["a"], 1);
  IncomingMessage second = reader.next();
  ASSERT_EQ(second.kind, Kind::Message);
  EXPECT_EQ(second.json["b"], 2);
  EXPECT_EQ(reader.next().kind, Kind::End);
}

TEST(MessageReader, GoesOnAfterBadJson) {
  std::istringstream in(framed("{nope") + framed("[1]"));
  MessageReader reader(in);
  EXPECT_EQ(reader.next().kind, Kind::BadJson);
  IncomingMessage next = reader.next();
  ASSERT_EQ(next.kind, Kind::Message);
  EXPECT_EQ(next.json, nlohmann::json::array({1}));
}

TEST(MessageReader, RefusesAnUnreadableHeader) {
  for (const std::string& header :
       std::vector<std::string>{"Content-Length: 12x\r\n\r\n", "Content-Length 3\r\n\r\n",
                                "Content-Type: a\r\n\r\n", std::string(5000, 'x') + "\r\n"}) {
    std::istringstream in(header + "{}");
    MessageReader reader(in);
    EXPECT_EQ(reader.next().kind, Kind::BadHeader) << header.substr(0, 40);
  }
}

TEST(MessageReader, EndsCleanlyInsideAMessage) {
  for (std::string text :
       {"Content-Len", "Content-Length: 10\r\n", "Content-Length: 10\r\n\r\n{}"}) {
    std::istringstream in(text);
    MessageReader reader(in);
    EXPECT_EQ(reader.next().kind, Kind::Truncated) << text;
  }
}

TEST(MessageReader, SkipsAMessageOverTheLimitUnallocated) {
  std::istringstream in(framed(std::string(100, ' ')) + framed("{}"));
  MessageReader reader(in, 50);
  IncomingMessage large = reader.next();
  ASSERT_EQ(large.kind, Kind::TooLarge);
  EXPECT_EQ(large.size, 100u);
  EXPECT_TRUE(reader.skipBody(large.size));
  EXPECT_EQ(reader.next().kind, Kind::Message);
}

TEST(MessageReader, ClaimsOfTwoGigabytesCostNothingUntilTheBytesCome) {
  std::istringstream in("Content-Length: 2000000000\r\n\r\n{}");
  MessageReader reader(in);
  IncomingMessage message = reader.next();
  EXPECT_EQ(message.kind, Kind::TooLarge);
  EXPECT_FALSE(reader.skipBody(message.size));
  std::istringstream under("Content-Length: 1000000000\r\n\r\n{}");
  EXPECT_EQ(MessageReader(under).next().kind, Kind::Truncated);
}

TEST(MessageWriter, FramesAndReplacesInvalidUtf8) {
  std::ostringstream out;
  MessageWriter writer(out);
  EXPECT_TRUE(writer.send(notificationMessage("m", {{"text", "a\xff"}})));
  std::istringstream in(out.str());
  IncomingMessage message = MessageReader(in).next();
  ASSERT_EQ(message.kind, Kind::Message);
  EXPECT_EQ(message.json["method"], "m");
  EXPECT_EQ(message.json["params"]["text"], "a\xEF\xBF\xBD");
}

}  // namespace
}  // namespace sfls
