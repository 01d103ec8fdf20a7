// The words of an exact-value comment (pov_writer.h lists its
// forms), read one by one: a keyword, any word, a number, a vector, a
// matrix. Each read says whether it matched; a comment that does not match
// its form is set aside and the statement is read instead.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string_view>
#include <vector>

namespace scene {

class PovCommentWords {
 public:
  explicit PovCommentWords(std::string_view text);

  // The next word, taken when it is `w`.
  bool word(std::string_view w);
  // The next word, whatever it is.
  std::optional<std::string_view> any();
  // The next word, taken when the whole of it reads as a number.
  bool number(double& out);
  bool vector(glm::dvec3& out) { return number(out.x) && number(out.y) && number(out.z); }
  // 16 numbers, row by row.
  bool matrix(glm::dmat4& out);
  // Every word was taken.
  bool done() const { return next_ == words_.size(); }

 private:
  std::vector<std::string_view> words_;
  std::size_t next_ = 0;
};

}  // namespace scene
