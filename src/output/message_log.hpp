#pragma once
// The message file (<prefix>.msg): command echo, model summary, simulation log, diagnostics.
// Every line is flushed at once so that a failed run keeps everything up to the failure. It
// holds no clock readings, so the same input gives the same bytes.

#include <cstdio>
#include <string>

#include "common/diagnostics.hpp"

namespace openmss::output {

class MessageLog {
 public:
  MessageLog() = default;
  ~MessageLog();
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;

  bool open(const std::string& path);
  void close();
  bool isOpen() const { return file_ != nullptr; }
  void line(const std::string& text);
  void diagnostic(const Diagnostic& d);

 private:
  std::FILE* file_ = nullptr;
};

}  // namespace openmss::output
