#include "expr/lexer.hpp"

#include <cctype>
#include <charconv>
#include <numbers>

namespace openmss::expr {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool isLetter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool isNameChar(char c) { return isLetter(c) || isDigit(c) || c == '_'; }

class Lexer {
 public:
  explicit Lexer(const std::string& text) : text_(text) {}

  LexResult run() {
    LexResult result;
    while (true) {
      skipBlanks();
      if (pos_ >= text_.size()) break;
      const char c = text_[pos_];
      if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
        if (!number(result)) return result;
      } else if (isLetter(c)) {
        name(result);
      } else if (!punctuation(result)) {
        return result;
      }
    }
    Token end;
    end.kind = TokenKind::End;
    end.column = static_cast<int>(text_.size()) + 1;
    result.tokens.push_back(end);
    return result;
  }

 private:
  char peek(std::size_t ahead) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
  int column(std::size_t index) const { return static_cast<int>(index) + 1; }
  void skipBlanks() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
  }

  // FORTRAN forms: 1  1.  .5  1.5  1E3  1.E-3  1.0E+007, each optionally followed by D for
  // degrees (90D = pi/2). A D followed by digits (FORTRAN's double-precision exponent, 1.0D0)
  // is refused because ADAMS reads a trailing D as degrees.
  bool number(LexResult& result) {
    const std::size_t start = pos_;
    bool integer = true;
    while (isDigit(peek(0))) ++pos_;
    if (peek(0) == '.') {
      integer = false;
      ++pos_;
      while (isDigit(peek(0))) ++pos_;
    }
    if (peek(0) == 'E' || peek(0) == 'e') {
      std::size_t look = 1;
      if (peek(look) == '+' || peek(look) == '-') ++look;
      if (!isDigit(peek(look))) return malformedNumber(result, start, pos_ + look);
      integer = false;
      pos_ += look;
      while (isDigit(peek(0))) ++pos_;
    }
    const std::size_t mantissaEnd = pos_;
    bool degrees = false;
    if (peek(0) == 'D' || peek(0) == 'd') {
      const char after = peek(1);
      const char afterSign = peek(2);
      if (isDigit(after) || ((after == '+' || after == '-') && isDigit(afterSign))) {
        std::size_t end = pos_ + 1;
        while (end < text_.size() && (isNameChar(text_[end]) || text_[end] == '+' ||
                                      text_[end] == '-' || text_[end] == '.')) {
          ++end;
        }
        const std::string spelled = text_.substr(start, end - start);
        const std::string mantissa = text_.substr(start, mantissaEnd - start);
        result.error = ExpressionError{
            column(start),
            "number '" + spelled + "' " + atColumn(column(start)) +
                " uses a D exponent, but a trailing D means degrees in ADAMS",
            "Write " + mantissa + "E" + text_.substr(mantissaEnd + 1, end - mantissaEnd - 1) +
                " for a power of ten; for an angle in degrees followed by more of the "
                "expression, put a blank after the D."};
        return false;
      }
      degrees = true;
      integer = false;
      ++pos_;
    }
    if (isNameChar(peek(0)) || peek(0) == '.') {
      std::size_t end = pos_;
      while (end < text_.size() && (isNameChar(text_[end]) || text_[end] == '.')) ++end;
      return malformedNumber(result, start, end);
    }
    double value = 0.0;
    const char* first = text_.data() + start;
    const char* last = text_.data() + mantissaEnd;
    const auto parsed = std::from_chars(first, last, value);
    if (parsed.ec != std::errc() || parsed.ptr != last) {
      return malformedNumber(result, start, pos_);
    }
    Token token;
    token.kind = TokenKind::Number;
    token.column = column(start);
    token.spelled = text_.substr(start, pos_ - start);
    token.number = degrees ? value * (std::numbers::pi / 180.0) : value;
    token.integerLiteral = integer;
    token.degrees = degrees;
    result.tokens.push_back(std::move(token));
    return true;
  }

  bool malformedNumber(LexResult& result, std::size_t start, std::size_t end) {
    const std::size_t stop = end > text_.size() ? text_.size() : end;
    const std::string spelled = text_.substr(start, stop - start);
    result.error = ExpressionError{
        column(start), "malformed number '" + spelled + "' " + atColumn(column(start)),
        "Write numbers as 1, 1., .5, 1.5E-3 or 90D (degrees), with no blank or letter inside, "
        "and an operator between a number and a name."};
    return false;
  }

  void name(LexResult& result) {
    const std::size_t start = pos_;
    while (isNameChar(peek(0))) ++pos_;
    Token token;
    token.kind = TokenKind::Name;
    token.column = column(start);
    token.spelled = text_.substr(start, pos_ - start);
    for (char c : token.spelled) {
      token.upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    if (peek(0) == '(') {
      token.callFollows = true;
    } else if (isBlank(peek(0))) {
      std::size_t look = pos_;
      while (look < text_.size() && isBlank(text_[look])) ++look;
      if (look < text_.size() && text_[look] == '(') token.blankBeforeParen = column(pos_);
    }
    result.tokens.push_back(std::move(token));
  }

  bool punctuation(LexResult& result) {
    Token token;
    token.column = column(pos_);
    const char c = text_[pos_];
    std::size_t length = 1;
    switch (c) {
      case '(':
        token.kind = TokenKind::LeftParen;
        break;
      case ')':
        token.kind = TokenKind::RightParen;
        break;
      case ',':
        token.kind = TokenKind::Comma;
        break;
      case ':':
        token.kind = TokenKind::Colon;
        break;
      case '+':
        token.kind = TokenKind::Plus;
        break;
      case '-':
        token.kind = TokenKind::Minus;
        break;
      case '/':
        token.kind = TokenKind::Slash;
        break;
      case '%':
        token.kind = TokenKind::Percent;
        break;
      case '[':
        token.kind = TokenKind::LeftBracket;
        break;
      case ']':
        token.kind = TokenKind::RightBracket;
        break;
      case '*':
        if (peek(1) == '*') {
          token.kind = TokenKind::Power;
          length = 2;
        } else {
          token.kind = TokenKind::Star;
        }
        break;
      default:
        result.error = ExpressionError{
            token.column,
            std::string("character '") + c + "' " + atColumn(token.column) +
                " is not part of the expression language",
            "Expressions use numbers, names, ( ) , : and the operators + - * / **."};
        return false;
    }
    token.spelled = text_.substr(pos_, length);
    pos_ += length;
    result.tokens.push_back(std::move(token));
    return true;
  }

  const std::string& text_;
  std::size_t pos_ = 0;
};

}  // namespace

LexResult tokenize(const std::string& text) { return Lexer(text).run(); }

std::string describe(const Token& token) {
  if (token.kind == TokenKind::End) return "the end of the expression";
  return "'" + token.spelled + "'";
}

}  // namespace openmss::expr
