#include "output/results_file_reader.hpp"

#include <libxml/xmlreader.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace openmss::output {
namespace {

constexpr const char* kNamespace = "http://www.mscsoftware.com/:xrf10";

struct ReaderDeleter {
  void operator()(xmlTextReader* r) const { xmlFreeTextReader(r); }
};

std::string text(const xmlChar* s) { return s ? reinterpret_cast<const char*>(s) : ""; }

std::string attribute(xmlTextReader* r, const char* name) {
  xmlChar* v = xmlTextReaderGetAttribute(r, reinterpret_cast<const xmlChar*>(name));
  std::string out = text(v);
  xmlFree(v);
  return out;
}

long integerAttribute(xmlTextReader* r, const char* name) {
  return std::strtol(attribute(r, name).c_str(), nullptr, 10);
}

// The numbers of a step's text; false at the first token that is not a number.
bool parseNumbers(const std::string& s, std::vector<double>& out, std::string* bad) {
  const char* p = s.c_str();
  while (true) {
    while (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t') ++p;
    if (*p == '\0') return true;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || (*end != '\0' && !std::strchr(" \n\r\t", *end))) {
      const char* stop = p;
      while (*stop && !std::strchr(" \n\r\t", *stop)) ++stop;
      *bad = std::string(p, stop);
      return false;
    }
    out.push_back(v);
    p = end;
  }
}

class Parser {
 public:
  Parser(xmlTextReader* r, const std::string& path, ResultsFileData& out)
      : r_(r), path_(path), out_(out) {
    // libxml2's own message goes into the error, not to stderr.
    xmlTextReaderSetErrorHandler(r_, &Parser::onError, this);
  }

  bool run(std::string* error) {
    int rc;
    while ((rc = xmlTextReaderRead(r_)) == 1) {
      if (xmlTextReaderNodeType(r_) != XML_READER_TYPE_ELEMENT) continue;
      if (!element(error)) return false;
    }
    if (rc != 0)
      return fail(error, "not well-formed XML" + (xmlError_.empty() ? "" : ": " + xmlError_));
    if (!sawResults_) return fail(error, "no <Results> element: not a results file");
    return true;
  }

 private:
  bool fail(std::string* error, const std::string& what) {
    if (error)
      *error = path_ + ":" + std::to_string(xmlTextReaderGetParserLineNumber(r_)) + ": " + what;
    return false;
  }

  bool element(std::string* error) {
    const std::string name = text(xmlTextReaderConstLocalName(r_));
    if (name == "Results") {
      if (text(xmlTextReaderConstNamespaceUri(r_)) != kNamespace)
        return fail(error, std::string("<Results> is not in the XRF namespace ") + kNamespace);
      sawResults_ = true;
    } else if (name == "Analysis") {
      out_.analysisName = attribute(r_, "name");
    } else if (name == "ModelInfo") {
      out_.title = attribute(r_, "title");
    } else if (name == "Units") {
      out_.angleUnits = attribute(r_, "angle");
      out_.lengthUnits = attribute(r_, "length");
      out_.massUnits = attribute(r_, "mass");
      out_.timeUnits = attribute(r_, "time");
    } else if (name == "Entity") {
      ResultsFileEntity e;
      e.name = attribute(r_, "name");
      e.entity = attribute(r_, "entity");
      e.entType = attribute(r_, "entType");
      e.objectId = integerAttribute(r_, "objectId");
      out_.entities.push_back(std::move(e));
    } else if (name == "Component") {
      if (out_.entities.empty()) return fail(error, "<Component> outside an <Entity>");
      ResultsFileComponent c;
      c.name = attribute(r_, "name");
      c.units = attribute(r_, "unitsValue");
      c.id = integerAttribute(r_, "id");
      if (c.id < 1) return fail(error, "component " + c.name + " has no positive id");
      out_.componentCount = std::max(out_.componentCount, c.id);
      out_.entities.back().components.push_back(std::move(c));
    } else if (name == "Data") {
      ResultsFileBlock b;
      b.name = attribute(r_, "name");
      b.id = integerAttribute(r_, "id");
      out_.blocks.push_back(std::move(b));
    } else if (name == "Step") {
      return step(error);
    } else if (name == "TerminationStatus") {
      out_.runStatus = attribute(r_, "runStatus");
    }
    return true;
  }

  bool step(std::string* error) {
    if (out_.blocks.empty()) return fail(error, "<Step> outside a <Data> block");
    ResultsFileStep s;
    s.type = attribute(r_, "type");
    xmlChar* body = xmlTextReaderReadString(r_);
    const std::string numbers = text(body);
    xmlFree(body);
    std::string bad;
    if (!parseNumbers(numbers, s.values, &bad)) return fail(error, "'" + bad + "' is not a number");
    // ADAMS's modelInput_001 step (type "input") holds the data set's configuration in a shape
    // of its own (fewer values than the map: observed in Adams 2016 output); every other step
    // holds one value per component.
    if (s.type != "input" && static_cast<long>(s.values.size()) != out_.componentCount)
      return fail(error, "a step of " + out_.blocks.back().name + " holds " +
                             std::to_string(s.values.size()) + " values for " +
                             std::to_string(out_.componentCount) + " components");
    out_.blocks.back().steps.push_back(std::move(s));
    return true;
  }

  static void onError(void* self, const char* message, xmlParserSeverities /*severity*/,
                      xmlTextReaderLocatorPtr /*locator*/) {
    std::string& e = static_cast<Parser*>(self)->xmlError_;
    if (!e.empty() || message == nullptr) return;  // the first message says what went wrong
    e = message;
    while (!e.empty() && (e.back() == '\n' || e.back() == ' ')) e.pop_back();
  }

  xmlTextReader* r_;
  std::string xmlError_;
  const std::string& path_;
  ResultsFileData& out_;
  bool sawResults_ = false;
};

}  // namespace

const ResultsFileEntity* ResultsFileData::findEntity(const std::string& name) const {
  for (const ResultsFileEntity& e : entities)
    if (e.name == name) return &e;
  return nullptr;
}

std::optional<long> ResultsFileData::componentId(const std::string& entity,
                                                 const std::string& component) const {
  if (const ResultsFileEntity* e = findEntity(entity))
    for (const ResultsFileComponent& c : e->components)
      if (c.name == component) return c.id;
  return std::nullopt;
}

std::vector<double> ResultsFileData::series(long id, const std::string& blockPrefix) const {
  std::vector<double> out;
  for (const ResultsFileBlock& b : blocks) {
    if (b.name.compare(0, blockPrefix.size(), blockPrefix) != 0) continue;
    for (const ResultsFileStep& s : b.steps)
      if (id >= 1 && static_cast<long>(s.values.size()) == componentCount)
        out.push_back(s.values[id - 1]);
  }
  return out;
}

bool readResultsFile(const std::string& path, ResultsFileData& out, std::string* error) {
  out = ResultsFileData{};
  // XML_PARSE_NONET: a results file never needs the network; XML_PARSE_HUGE: long steps.
  std::unique_ptr<xmlTextReader, ReaderDeleter> reader(
      xmlReaderForFile(path.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_HUGE));
  if (!reader) {
    if (error) *error = path + ": cannot be opened";
    return false;
  }
  return Parser(reader.get(), path, out).run(error);
}

}  // namespace openmss::output
