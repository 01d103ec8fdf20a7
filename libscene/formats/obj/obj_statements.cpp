#include "libscene/formats/obj/obj_statements.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <set>

#include "libscene/text/number.h"
#include "libscene/text/reader_support.h"
#include "libscene/text/text_lines.h"

namespace scene {

namespace {

// What other programs write and a scene has no use for: skipped in silence.
constexpr std::array<std::string_view, 5> kSilent = {"vn", "vt", "vp", "s", "mg"};
// The most distinct unknown statements noted: a file of garbage gets a
// bounded list.
constexpr std::size_t kMaxIgnoredNotes = 16;
constexpr std::size_t kMaxNameInMessages = 64;

struct Word {
  std::string_view text;
  std::uint32_t column = 0;
};

bool isSpaceOrTab(char c) {
  return c == ' ' || c == '\t';
}

constexpr std::size_t kMaxKeptWords = 9;

// Calls f(word) for each blank-separated word of `line` from `from` on,
// until f returns false.
template <typename F>
void forEachWord(std::string_view line, std::size_t from, F&& f) {
  for (std::size_t i = from; i < line.size();) {
    while (i < line.size() && isSpaceOrTab(line[i])) ++i;
    std::size_t start = i;
    while (i < line.size() && !isSpaceOrTab(line[i])) ++i;
    if (i > start &&
        !f(Word{line.substr(start, i - start), static_cast<std::uint32_t>(start + 1)})) {
      return;
    }
  }
}

std::string printableName(std::string_view name) {
  return objPrintableName(name);
}

class StatementReader {
 public:
  StatementReader(const ReadOptions& options, DiagnosticList& out)
      : options_(options), out_(out), maxCorners_(3 * options.obj.maxVertices) {}

  ObjStatements read(std::string_view text);

 private:
  bool line(std::string_view line);
  bool vertex(const std::vector<Word>& words);
  bool face(std::string_view l, const Word& keyword);
  std::optional<std::uint32_t> corner(const Word& word);
  void startGroup(std::string_view name, SourceSpan span);
  bool comment(std::string_view line);
  void ignored(std::string_view keyword, const Word& word);
  void syntax(const Word& word, std::string message) {
    out_.error(DiagnosticCode::ObjSyntax, span(word), std::move(message));
  }
  SourceSpan span(const Word& w) const {
    return {line_, w.column, static_cast<std::uint32_t>(w.text.size())};
  }

  const ReadOptions& options_;
  DiagnosticList& out_;
  std::size_t maxCorners_;
  std::size_t corners_ = 0;
  std::uint32_t line_ = 0;
  ObjStatements result_;
  // The group that faces go to: set by `o`/`g`, kept apart until its first
  // face so that a group without faces is no object.
  ObjGroup pending_;
  bool pendingHasFaces_ = false;
  std::optional<ObjectComment> comment_;
  std::string material_;
  SourceSpan materialSpan_;
  std::set<std::string, std::less<>> noted_;
  bool staleNoted_ = false;
};

ObjStatements StatementReader::read(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  pending_.name = "default";
  while (!text.empty() && !out_.full()) {
    ++line_;
    std::size_t end = text.find('\n');
    std::string_view l = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (!line(l)) break;
  }
  if (pendingHasFaces_) result_.groups.push_back(std::move(pending_));
  return std::move(result_);
}

// One line; false stops the reading (a limit was reached).
bool StatementReader::line(std::string_view l) {
  std::size_t first = l.find_first_not_of(" \t");
  if (first == std::string_view::npos) return true;
  if (l[first] == '#') return comment(l.substr(first));
  // A statement other than a face has at most 8 words: more are counted,
  // not kept, so that a line of millions costs nothing.
  std::vector<Word> words;
  std::size_t count = 0;
  forEachWord(l, first, [&](const Word& w) {
    if (++count <= kMaxKeptWords) words.push_back(w);
    return count <= kMaxKeptWords || words[0].text != "v";
  });
  std::string_view keyword = words[0].text;
  auto invalid = std::find_if(keyword.begin(), keyword.end(), [](char c) {
    return !(std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  });
  if (invalid != keyword.end()) {
    syntax(words[0], "this line does not start with an OBJ statement: it starts with " +
                         (*invalid >= ' ' && *invalid <= '~'
                              ? "'" + printableName(keyword) + "'"
                              : "a " + describeInvalidByte(static_cast<unsigned char>(*invalid))));
    return true;
  }
  std::string_view rest = l.substr(words[0].column - 1 + keyword.size());
  std::size_t restStart = rest.find_first_not_of(" \t");
  rest = restStart == std::string_view::npos ? std::string_view() : rest.substr(restStart);
  if (keyword == "v") return vertex(words);
  if (keyword == "f") return face(l, words[0]);
  if (keyword == "o" || keyword == "g") {
    startGroup(rest, span(words[0]));
    return true;
  }
  if (keyword == "usemtl") {
    material_ = std::string(rest);
    materialSpan_ = span(words[0]);
    if (pendingHasFaces_ && material_ != pending_.material) pending_.severalMaterials = true;
    return true;
  }
  if (keyword == "mtllib") {
    for (std::size_t i = 1; i < words.size(); ++i) {
      result_.libraries.push_back({std::string(words[i].text), span(words[i])});
    }
    return true;
  }
  if (std::find(kSilent.begin(), kSilent.end(), keyword) == kSilent.end()) {
    ignored(keyword, words[0]);
  }
  return true;
}

bool StatementReader::comment(std::string_view l) {
  if (!l.starts_with(kObjExactComment) || l.size() == kObjExactComment.size() ||
      !isSpaceOrTab(l[kObjExactComment.size()])) {
    return true;
  }
  std::optional<ObjectComment> object;
  if (readComment(l.substr(kObjExactComment.size()), result_.comments, object)) {
    if (object) comment_ = std::move(object);
  } else if (!staleNoted_) {
    staleNoted_ = true;
    out_.note(DiagnosticCode::ObjIgnored, {line_, 1, static_cast<std::uint32_t>(l.size())},
              "this '" + std::string(kObjExactComment) +
                  "' comment does not read as one the OBJ writer writes: it is ignored");
  }
  return true;
}

void StatementReader::ignored(std::string_view keyword, const Word& word) {
  if (noted_.size() >= kMaxIgnoredNotes || noted_.contains(keyword)) return;
  noted_.emplace(keyword);
  out_.note(DiagnosticCode::ObjIgnored, span(word),
            "'" + printableName(keyword) +
                "' statements are ignored: a scene holds the four primitives' meshes alone");
}

void StatementReader::startGroup(std::string_view name, SourceSpan span) {
  if (pendingHasFaces_) result_.groups.push_back(std::move(pending_));
  pending_ = ObjGroup{};
  pendingHasFaces_ = false;
  pending_.name = name.empty() ? "(unnamed)" : printableName(name);
  pending_.span = span;
  // A comment describes the group that follows it, and no other.
  pending_.comment = std::move(comment_);
  comment_.reset();
}

bool StatementReader::vertex(const std::vector<Word>& words) {
  if (words.size() < 4 || words.size() > 8) {
    syntax(words[0],
           "a vertex is 'v x y z', with an optional w or r g b; this one has " +
               (words.size() > 8 ? std::string("more than 7") : std::to_string(words.size() - 1)) +
               " numbers");
    return true;
  }
  if (result_.positions.size() >= options_.obj.maxVertices) {
    out_.error(DiagnosticCode::ObjTooLarge, span(words[0]),
               "the file has more than " + std::to_string(options_.obj.maxVertices) +
                   " vertices: reading stops here");
    return false;
  }
  double xyz[3];
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const Word& w = words[i + 1];
    ParsedNumber p = parseNumber(w.text);
    // Worded as the scene file reader words them (reader_support.cpp).
    if (p.status == NumberStatus::Syntax) {
      std::string shown(w.text.substr(0, 40));
      if (w.text.size() > 40) shown += "...";
      out_.error(DiagnosticCode::InvalidNumber, span(w),
                 "'" + printableName(shown) + "' is not a number")
          .hint = numberSyntaxReason(w.text);
      ok = false;
    } else if (p.status == NumberStatus::Overflow) {
      out_.error(DiagnosticCode::NumberOutOfRange, span(w),
                 "number is too large for a 64-bit double");
      ok = false;
    } else if (p.status == NumberStatus::Underflow) {
      out_.error(DiagnosticCode::NumberOutOfRange, span(w),
                 "number is too small for a 64-bit double: it would round to 0");
      ok = false;
    }
    xyz[i] = p.value;
  }
  // A vertex that does not read still takes its number, so that the
  // indices after it keep their meaning.
  result_.positions.emplace_back(ok ? glm::dvec3(xyz[0], xyz[1], xyz[2]) : glm::dvec3(0.0));
  return true;
}

std::optional<std::uint32_t> StatementReader::corner(const Word& w) {
  std::string_view text = w.text;
  std::string_view index = text.substr(0, text.find('/'));
  long long value = 0;
  auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), value);
  bool whole = ec == std::errc() && end == index.data() + index.size() && !index.empty();
  // The texture and normal indices are not used, but must be numbers.
  for (std::size_t slash = text.find('/'); whole && slash != std::string_view::npos;
       slash = text.find('/', slash + 1)) {
    std::string_view part = text.substr(slash + 1, text.find('/', slash + 1) - slash - 1);
    whole = std::all_of(part.begin(), part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) || c == '-';
    });
  }
  if (!whole || std::count(text.begin(), text.end(), '/') > 2) {
    syntax(w, "'" + printableName(text) + "' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
    return std::nullopt;
  }
  long long count = static_cast<long long>(result_.positions.size());
  long long resolved = value < 0 ? count + value : value - 1;
  if (value == 0 || resolved < 0 || resolved >= count) {
    syntax(w, "vertex " + std::to_string(value) + " does not exist: " + std::to_string(count) +
                  " vertices come before this face");
    return std::nullopt;
  }
  return static_cast<std::uint32_t>(resolved);
}

bool StatementReader::face(std::string_view l, const Word& keyword) {
  std::size_t from = keyword.column - 1 + keyword.text.size();
  // Counted first: a face over the limit is refused before a corner is kept.
  std::size_t count = 0;
  forEachWord(l, from, [&count](const Word&) { return ++count, true; });
  if (count < 3) {
    syntax(keyword, "a face needs at least three corners");
    return true;
  }
  std::size_t triangles = count - 2;
  if (corners_ + 3 * triangles > maxCorners_) {
    out_.error(DiagnosticCode::ObjTooLarge, span(keyword),
               "the faces have more than " + std::to_string(maxCorners_) +
                   " triangle corners (three times the vertex limit): reading stops here");
    return false;
  }
  if (!pendingHasFaces_) {
    if (result_.groups.size() + result_.comments.lights.size() >= options_.maxObjects) {
      reportTooManyObjects(span(keyword), options_.maxObjects, out_);
      return false;
    }
    pendingHasFaces_ = true;
    if (!pending_.span.known()) pending_.span = span(keyword);
    pending_.material = material_;
    pending_.materialSpan = materialSpan_;
  }
  // A polygon is split as a fan about its first corner.
  std::vector<std::uint32_t>& corners = pending_.corners;
  std::size_t before = corners.size();
  std::uint32_t first = 0, previous = 0;
  std::size_t k = 0;
  bool ok = true;
  forEachWord(l, from, [&](const Word& w) {
    std::optional<std::uint32_t> c = corner(w);
    if (!c) return ok = false;
    if (k == 0) first = *c;
    if (k >= 2) corners.insert(corners.end(), {first, previous, *c});
    previous = *c;
    ++k;
    return true;
  });
  if (!ok) corners.resize(before);
  corners_ += 3 * triangles;
  return true;
}

}  // namespace

std::string objPrintableName(std::string_view name) {
  std::string out;
  for (char c : name.substr(0, kMaxNameInMessages)) {
    out += c >= ' ' && c <= '~' ? c : '?';
  }
  return out;
}

ObjStatements readObjStatements(std::string_view text, const ReadOptions& options,
                                DiagnosticList& out) {
  return StatementReader(options, out).read(text);
}

}  // namespace scene
