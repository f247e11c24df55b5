#include "output/results_file.hpp"

#include <libxml/encoding.h>
#include <libxml/xmlwriter.h>

#include <charconv>
#include <cstdio>
#include <filesystem>

namespace openmss::output {
namespace {

constexpr const char* kNamespace = "http://www.mscsoftware.com/:xrf10";

const xmlChar* x(const char* s) { return reinterpret_cast<const xmlChar*>(s); }
const xmlChar* x(const std::string& s) { return x(s.c_str()); }

}  // namespace

std::string formatResultValue(double value, int decimalPlaces) {
  if (value == 0.0) return "0";  // -0 too: a sign on zero carries nothing for a reader
  char buf[64];
  std::to_chars_result r{};
  if (decimalPlaces >= 17) {
    // Shortest text that reads back as this very double (C++17 to_chars round-trip guarantee).
    r = std::to_chars(buf, buf + sizeof buf, value);
  } else {
    // decimalPlaces digits after the point in scientific notation (decimalPlaces + 1
    // significant digits), trailing zeros dropped as %g does.
    r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, decimalPlaces + 1);
  }
  std::string s(buf, r.ptr);
  for (char& c : s)
    if (c == 'e') c = 'E';  // as ADAMS writes exponents
  return s;
}

ResultsFileWriter::~ResultsFileWriter() { close(); }

bool ResultsFileWriter::check(int rc, const char* what) {
  if (rc >= 0) return true;
  if (error_.empty())
    error_ = std::string("cannot write the results file ") + path_ + " (" + what + ")";
  return false;
}

bool ResultsFileWriter::open(const std::string& path, const model::Model& m,
                             const model::ResultsSettings& rs, const ResultsFileHeader& h,
                             std::string* error) {
  close();
  error_.clear();
  path_ = path;
  layout_ = resultsLayout(m, rs);
  decimalPlaces_ = rs.decimalPlaces;
  dataOpen_ = false;
  newBlock_ = true;
  runFailed_ = false;
  blocks_ = 0;
  for (int& c : kindCounts_) c = 0;
  writer_ = xmlNewTextWriterFilename(path.c_str(), 0);
  if (writer_ == nullptr) {
    if (error) *error = "cannot create the results file " + path;
    return false;
  }
  // One element per line, no indentation: the layout of the files ADAMS writes.
  xmlTextWriterSetIndent(writer_, 1);
  xmlTextWriterSetIndentString(writer_, x(""));
  const std::string file = std::filesystem::path(path).filename().string();
  bool ok = check(xmlTextWriterStartDocument(writer_, "1.0", "UTF-8", nullptr), "header");
  const auto start = [&](const char* name) {
    ok = ok && check(xmlTextWriterStartElement(writer_, x(name)), name);
  };
  const auto attr = [&](const char* name, const std::string& value) {
    ok = ok && check(xmlTextWriterWriteAttribute(writer_, x(name), x(value)), name);
  };
  const auto end = [&]() { ok = ok && check(xmlTextWriterEndElement(writer_), "end"); };
  start("Results");
  attr("xmlns", kNamespace);
  start("Bibliography");
  // No absolute path, host, user or wall-clock date: the file must be the same on every run
  // and machine (docs/output-files.md).
  start("File");
  attr("URI", "file://" + file);
  attr("schema", "xrf");
  attr("version", "2.0.0.0");
  attr("publicationDate", h.stamp + "+00:00");
  end();
  start("Corporation");
  attr("author", "OpenMSS");
  attr("URI", "-unknown-");
  end();
  start("Author");
  attr("user", "-unknown-");
  attr("name", "-unknown name-");
  end();
  start("Revision");
  attr("version", "1");
  attr("derivedFrom", "-unknown-");
  start("Comment");
  ok = ok && check(xmlTextWriterWriteString(writer_, x(rs.comment)), "comment");
  end();
  end();
  end();  // Bibliography
  start("Analysis");
  attr("name", h.analysisName);
  attr("executionDate", h.stamp);
  attr("Solver", h.solver + " " + h.version);
  attr("script", "-unknown-");
  start("Bibliography");
  start("Application");
  attr("name", h.solver);
  attr("version", h.version);
  end();
  end();
  start("ModelInfo");
  attr("title", m.title);
  attr("creationDate", "-unknown-");
  attr("checksum", "-unknown-");
  end();
  start("Units");
  attr("angle", layout_.units.angle);
  attr("length", layout_.units.length);
  attr("mass", layout_.units.mass);
  attr("time", layout_.units.time);
  end();
  start("StepMap");
  attr("name", "map_001");
  for (const ResultsEntity& e : layout_.entities) {
    start("Entity");
    attr("name", e.name);
    if (!e.entType.empty()) {
      attr("entity", e.entity);
      attr("entType", e.entType);
      attr("objectId", std::to_string(e.objectId));
    }
    for (int c : e.components) {
      start("Component");
      attr("name", layout_.components[c].name);
      if (!layout_.components[c].units.empty()) attr("unitsValue", layout_.components[c].units);
      attr("id", std::to_string(c + 1));
      end();
    }
    end();
  }
  end();  // StepMap
  ok = ok && check(xmlTextWriterFlush(writer_), "flush");
  if (!ok) {
    if (error) *error = error_;
    xmlFreeTextWriter(writer_);
    writer_ = nullptr;
    return false;
  }
  return true;
}

bool ResultsFileWriter::startBlock(OutputKind kind) {
  bool ok = true;
  if (dataOpen_) ok = check(xmlTextWriterEndElement(writer_), "Data");
  dataOpen_ = false;
  char number[16];
  std::snprintf(number, sizeof number, "_%03d", ++kindCounts_[static_cast<int>(kind)]);
  ok = ok && check(xmlTextWriterStartElement(writer_, x("Data")), "Data") &&
       check(xmlTextWriterWriteAttribute(writer_, x("name"),
                                         x(std::string(outputKindName(kind)) + number)),
             "Data") &&
       check(xmlTextWriterWriteAttribute(writer_, x("id"), x(std::to_string(++blocks_))), "Data");
  dataOpen_ = ok;
  blockKind_ = kind;
  newBlock_ = false;
  return ok;
}

bool ResultsFileWriter::writeStep(const OutputFrame& frame) {
  if (writer_ == nullptr) return false;
  if (const std::string bad = layout_.mismatch(frame); !bad.empty()) {
    if (error_.empty())
      error_ = "the results file " + path_ + " cannot hold this step: " + bad +
               " (the model changed its elements after the file was opened)";
    return false;
  }
  if ((newBlock_ || !dataOpen_ || frame.kind != blockKind_) && !startBlock(frame.kind))
    return false;
  // The step's numbers in id order, one line per group (a part's positions, one element's
  // forces, ...), as ADAMS lays them out; readers split on any white space.
  std::string text = "\n";
  int group = -1;
  for (const ResultsComponent& c : layout_.components) {
    if (group >= 0) text += c.group == group ? ' ' : '\n';
    group = c.group;
    text += formatResultValue(c.value(frame), decimalPlaces_);
  }
  text += '\n';
  return check(xmlTextWriterStartElement(writer_, x("Step")), "Step") &&
         check(xmlTextWriterWriteAttribute(writer_, x("type"), x(outputKindName(frame.kind))),
               "Step") &&
         check(xmlTextWriterWriteString(writer_, x(text)), "Step") &&
         check(xmlTextWriterEndElement(writer_), "Step") &&
         check(xmlTextWriterFlush(writer_), "flush");
}

void ResultsFileWriter::close() {
  if (writer_ == nullptr) return;
  if (dataOpen_) check(xmlTextWriterEndElement(writer_), "Data");
  dataOpen_ = false;
  check(xmlTextWriterStartElement(writer_, x("TerminationStatus")), "TerminationStatus");
  check(xmlTextWriterWriteAttribute(writer_, x("runTermObject"), x("")), "TerminationStatus");
  check(
      xmlTextWriterWriteAttribute(writer_, x("runStatus"), x(runFailed_ ? "Failed" : "Successful")),
      "TerminationStatus");
  check(xmlTextWriterEndElement(writer_), "TerminationStatus");
  // Ends Analysis and Results, and the document.
  check(xmlTextWriterEndDocument(writer_), "end of document");
  xmlFreeTextWriter(writer_);  // flushes and closes the file
  writer_ = nullptr;
}

}  // namespace openmss::output
