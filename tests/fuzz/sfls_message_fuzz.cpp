// libFuzzer target: sfls's message reader on any bytes. It must end (no
// message claims more than the bytes hold), never allocate for a length the
// bytes do not back, and every message it returns must be JSON that writes
// back out.
#include <sstream>
#include <string>

#include "tests/fuzz/fuzz_input.h"
#include "tools/sfls/json_rpc.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in{std::string(fuzz::asText(data, size))};
  // A small limit, so that skipping a message over it is reached too.
  sfls::MessageReader reader(in, 4096);
  for (std::size_t messages = 0; messages <= size; ++messages) {
    sfls::IncomingMessage message = reader.next();
    using Kind = sfls::IncomingMessage::Kind;
    if (message.kind == Kind::End || message.kind == Kind::Truncated ||
        message.kind == Kind::BadHeader) {
      return 0;
    }
    if (message.kind == Kind::TooLarge && !reader.skipBody(message.size)) return 0;
    if (message.kind == Kind::Message) {
      std::ostringstream out;
      sfls::MessageWriter writer(out);
      if (!writer.send(message.json)) fuzz::propertyFailed("a message read cannot be written", "");
    }
  }
  fuzz::propertyFailed("the reader returned more messages than the input has bytes", "");
}
