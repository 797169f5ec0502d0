// text_scanner.h — private to the mesh readers: a whitespace tokenizer over an in-memory text that tracks line numbers,
// collects `#` comments when asked, and parses numbers with std::from_chars (no iostreams, no locale, no allocation).
//
// Every failure is an InputError "SOURCE:LINE: what was expected, found what" so the OBJ, OFF and ASCII-PLY readers
// report bad bytes the same way. Tokens quoted in messages are truncated and have non-printable bytes escaped, since
// the readers are fuzzed with arbitrary binary input.
//
// Used by obj_io.cpp, off_io.cpp and ply_io.cpp; not installed.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic::detail {

// A token as it may appear in an error message: at most 40 bytes, non-printable bytes as \xNN.
inline std::string quoteToken(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

// Parses a whole token as a signed integer; false if the token is not exactly an integer in range. A leading '+' is
// accepted because several writers emit it (std::from_chars alone rejects it).
inline bool parseInteger(std::string_view token, long long& value) {
  const char* b = token.data();
  const char* e = b + token.size();
  if (b != e && *b == '+') {
    ++b;
    if (b == e || *b == '+' || *b == '-') return false;
  }
  const auto r = std::from_chars(b, e, value);
  return r.ec == std::errc() && r.ptr == e;
}

// Parses a whole token as a real number (decimal or scientific; also "inf"/"nan", which callers reject by name).
inline bool parseReal(std::string_view token, double& value) {
  const char* b = token.data();
  const char* e = b + token.size();
  if (b != e && *b == '+') {
    ++b;
    if (b == e || *b == '+' || *b == '-') return false;
  }
  const auto r = std::from_chars(b, e, value, std::chars_format::general);
  return r.ec == std::errc() && r.ptr == e;
}

class TextScanner {
 public:
  // `firstLine` is the line number of text[0] (the PLY reader starts the scanner after its header).
  TextScanner(std::string_view text, std::string source, int firstLine = 1)
      : text_(text), source_(std::move(source)), line_(firstLine) {}

  // Treat '#' to end of line as a comment (OBJ, OFF). Comment texts (after the '#', leading blanks removed) are
  // appended with their line numbers to `sink` when it is not null.
  void enableHashComments(std::vector<std::pair<int, std::string_view>>* sink) {
    hashComments_ = true;
    commentSink_ = sink;
  }

  int line() const { return line_; }
  std::size_t remainingBytes() const { return text_.size() - pos_; }

  // The next token anywhere ahead (crossing line breaks and comments); empty at end of text.
  std::string_view token() {
    for (;;) {
      skipBlanks();
      if (pos_ == text_.size()) return {};
      const char c = text_[pos_];
      if (c == '\n') {
        ++pos_;
        ++line_;
      } else if (hashComments_ && c == '#') {
        skipComment();
      } else {
        return takeToken();
      }
    }
  }

  // The next token on the current line; empty when the line (or the text) has no more tokens. Does not consume '\n'.
  std::string_view tokenOnLine() {
    skipBlanks();
    if (pos_ == text_.size() || text_[pos_] == '\n') return {};
    if (hashComments_ && text_[pos_] == '#') {
      skipComment();
      return {};
    }
    return takeToken();
  }

  // Discards the rest of the current line and its '\n' (comments on it are still collected). False at end of text.
  bool nextLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') {
      if (hashComments_ && text_[pos_] == '#') {
        skipComment();
      } else {
        ++pos_;
      }
    }
    if (pos_ == text_.size()) return false;
    ++pos_;
    ++line_;
    return true;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line_) + ": " + what);
  }

  // "expected <what>, found <token>" (or "found end of file"/"found end of line").
  [[noreturn]] void failExpected(const std::string& what, std::string_view found, bool lineBound = false) const {
    // At end of file, point at the last line that had content rather than at the empty line after it.
    if (found.empty() && pos_ == text_.size() && lastTokenLine_ > 0)
      throw InputError(source_ + ":" + std::to_string(lastTokenLine_) + ": expected " + what + ", found end of file");
    fail("expected " + what + ", found " +
         (found.empty() ? std::string(lineBound && pos_ < text_.size() ? "end of line" : "end of file")
                        : quoteToken(found)));
  }

  // The next token (anywhere ahead, or on this line when `lineBound`) as an integer / a real number. `what` is a
  // callable returning the description of the expected value; it is only called to build an error message, so that
  // reading a million numbers builds no strings.
  template <class What>
  long long readInteger(const What& what, bool lineBound = false) {
    const std::string_view t = lineBound ? tokenOnLine() : token();
    long long v = 0;
    if (!parseInteger(t, v)) failExpected(what() + " (an integer)", t, lineBound);
    return v;
  }
  template <class What>
  double readReal(const What& what, bool lineBound = false) {
    const std::string_view t = lineBound ? tokenOnLine() : token();
    double v = 0;
    if (!parseReal(t, v)) failExpected(what() + " (a number)", t, lineBound);
    return v;
  }
  // A real that must be finite (coordinates, lengths): NaN and infinities are named as such.
  template <class What>
  double readFinite(const What& what, bool lineBound = false) {
    const double v = readReal(what, lineBound);
    if (!std::isfinite(v)) fail(what() + " is " + formatNumber(v) + "; expected a finite number");
    return v;
  }

 private:
  void skipBlanks() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else {
        break;
      }
    }
  }
  void skipComment() {
    const std::size_t begin = pos_ + 1;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if (commentSink_ != nullptr) {
      std::string_view body = text_.substr(begin, pos_ - begin);
      while (!body.empty() && (body.front() == ' ' || body.front() == '\t')) body.remove_prefix(1);
      while (!body.empty() && (body.back() == '\r' || body.back() == ' ' || body.back() == '\t')) body.remove_suffix(1);
      commentSink_->emplace_back(line_, body);
    }
  }
  std::string_view takeToken() {
    const std::size_t begin = pos_;
    lastTokenLine_ = line_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') break;
      if (hashComments_ && c == '#') break;
      ++pos_;
    }
    return text_.substr(begin, pos_ - begin);
  }

  std::string_view text_;
  std::string source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int lastTokenLine_ = 0;
  bool hashComments_ = false;
  std::vector<std::pair<int, std::string_view>>* commentSink_ = nullptr;
};

}  // namespace conformesh::intrinsic::detail
