#include "output/message_log.hpp"

namespace openmss::output {

MessageLog::~MessageLog() { close(); }

bool MessageLog::open(const std::string& path) {
  close();
  file_ = std::fopen(path.c_str(), "w");
  return file_ != nullptr;
}

void MessageLog::close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

void MessageLog::line(const std::string& text) {
  if (!file_) return;
  std::fputs(text.c_str(), file_);
  std::fputc('\n', file_);
  std::fflush(file_);
}

void MessageLog::diagnostic(const Diagnostic& d) { line(format(d)); }

}  // namespace openmss::output
