// The tabular output file (.out) end to end: runs the openmss program on the nine ADAMS joint
// cases and the piston example and reads the .out with a parser of its own (split on white
// space, as the layout promises), then checks it against independent truths: every value the
// .req of the same run holds (the same double printed the same way, so equal exactly), and
// the magnitude columns F1/F5 against sqrt(x^2 + y^2 + z^2) of the printed components. A run
// that fails midway keeps every step before the failure. Layout: docs/output-files.md, "The
// tabular output file (.out)".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"
#include "support/validation_data.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;
using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

struct OutTable {
  std::string type;
  std::vector<std::string> names;         // TIME first
  std::vector<std::vector<double>> rows;  // every page's rows, in file order; time first
};

struct OutFile {
  std::map<long, OutTable> tables;
  std::vector<std::string> blocks;  // analysis block names, in order of first appearance
  std::string status;               // "Successful" or "Failed" from the closing line
  int pages = 0;
};

// An independent reader of the layout docs/output-files.md describes.
OutFile parseOut(const fs::path& path) {
  OutFile f;
  std::istringstream in(slurp(path));
  std::string line;
  OutTable* table = nullptr;
  int headerLines = 0;  // lines of the current table's header still to come
  while (std::getline(in, line)) {
    if (line.rfind(" Analysis ", 0) == 0) {
      ++f.pages;
      const std::string name = line.substr(10, line.find(',') - 10);
      if (f.blocks.empty() || f.blocks.back() != name) f.blocks.push_back(name);
      table = nullptr;
    } else if (line.rfind(" End of the run: ", 0) == 0) {
      f.status = line.substr(17);
      table = nullptr;
    } else if (line.rfind(" REQUEST/", 0) == 0) {
      std::istringstream w(line.substr(9));
      long id = 0;
      std::string type;
      w >> id >> type;
      table = &f.tables[id];
      table->type = type;
      headerLines = 3;  // comment, names, units
    } else if (table && headerLines > 0) {
      if (headerLines == 2) {
        std::istringstream w(line);
        std::vector<std::string> names;
        for (std::string n; w >> n;) names.push_back(n);
        if (table->names.empty()) table->names = names;
        EXPECT_EQ(table->names, names) << "the columns of a table changed between pages";
      }
      --headerLines;
    } else if (table && !line.empty() && line[0] == ' ') {
      std::istringstream w(line);
      std::vector<double> row;
      for (std::string v; w >> v;) row.push_back(std::stod(v));
      EXPECT_EQ(row.size(), table->names.size()) << line;
      table->rows.push_back(row);
    } else {
      table = nullptr;  // a blank line or a rule ends the table
    }
  }
  return f;
}

// Every .req value equals the .out value of the same request, column and step exactly (the
// same double printed with the same "%.5E"). Returns the number of values compared.
long compareWithRequestFile(const fs::path& req, const OutFile& out, long* requests, long* steps) {
  std::string err;
  const auto r = readRequestFile(req.string(), &err);
  EXPECT_TRUE(r.has_value()) << err;
  if (!r) return 0;
  *requests = static_cast<long>(r->entries.size());
  *steps = static_cast<long>(r->steps.size());
  long compared = 0;
  for (std::size_t e = 0; e < r->entries.size(); ++e) {
    const auto it = out.tables.find(r->entries[e].id);
    if (it == out.tables.end()) {
      ADD_FAILURE() << "REQUEST/" << r->entries[e].id << " has no table";
      continue;
    }
    const OutTable& t = it->second;
    EXPECT_EQ(t.rows.size(), r->steps.size()) << "REQUEST/" << r->entries[e].id;
    // The .req's six columns F2 F3 F4 F6 F7 F8 in the .out: after TIME and F1, and after F5
    // (a DISPLACEMENT table has no F5 column).
    const bool displacement = t.type == "DISPLACEMENT";
    const int at[6] = {2, 3, 4, displacement ? 5 : 6, displacement ? 6 : 7, displacement ? 7 : 8};
    for (std::size_t k = 0; k < r->steps.size() && k < t.rows.size(); ++k) {
      EXPECT_EQ(t.rows[k][0], r->steps[k].time);
      for (int c = 0; c < 6; ++c) {
        EXPECT_EQ(t.rows[k][static_cast<std::size_t>(at[c])], r->steps[k].rows[e][c])
            << "REQUEST/" << r->entries[e].id << " step " << k << " column " << c;
        ++compared;
      }
    }
  }
  return compared;
}

// F1 = |(F2, F3, F4)| and F5 = |(F6, F7, F8)| for the VELOCITY, ACCELERATION and FORCE
// tables, F1 for DISPLACEMENT. Each printed value is within 5e-6 of its size (six significant
// digits); the norm of components each off by at most that fraction is off by at most that
// fraction of the norm, and so is the printed norm: 1.1e-5 of the magnitude covers both.
long checkMagnitudes(const OutFile& out) {
  long checked = 0;
  for (const auto& [id, t] : out.tables) {
    if (t.type == "EXPRESSIONS") continue;  // F1 and F5 are the user's own expressions
    const bool displacement = t.type == "DISPLACEMENT";
    for (const auto& row : t.rows) {
      const double m1 = std::sqrt(row[2] * row[2] + row[3] * row[3] + row[4] * row[4]);
      EXPECT_NEAR(row[1], m1, 1.1e-5 * m1 + 1e-300) << "REQUEST/" << id;
      ++checked;
      if (displacement) continue;
      const double m5 = std::sqrt(row[6] * row[6] + row[7] * row[7] + row[8] * row[8]);
      EXPECT_NEAR(row[5], m5, 1.1e-5 * m5 + 1e-300) << "REQUEST/" << id;
      ++checked;
    }
  }
  return checked;
}

TEST(TabularFile, NineJointCasesHoldTheRequestFileValuesAndTheMagnitudes) {
  const fs::path joints = openmss::testing::adamsJointsDir();
  const char* cases[] = {"Revolute_Case01",  "Revolute_Case02",  "Spherical_Case01",
                         "Spherical_Case02", "Universal_Case01", "Universal_Case02",
                         "Prismatic_Case01", "Prismatic_Case02", "Cylindrical_Case01"};
  long total = 0, magnitudes = 0;
  for (const char* name : cases) {
    const fs::path dir = scratch(std::string("out-") + name);
    const std::string model = "test_" + std::string(name);
    fs::copy_file(joints / name / (model + ".adm"), dir / (model + ".adm"));
    write(dir / "run.acf", model +
                               ".adm\nout\noutput/noseparator\n"
                               "integrator/gstiff, error=1.0e-4\n"
                               "simulate/transient, end=0.1, dtout=0.01\nstop\n");
    const Result r = run("run run.acf --quiet", dir);
    ASSERT_EQ(r.status, 0) << name << "\n" << r.output;
    const OutFile out = parseOut(dir / "out.out");
    EXPECT_EQ(out.status, "Successful") << name;
    long requests = 0, steps = 0;
    const long n = compareWithRequestFile(dir / "out.req", out, &requests, &steps);
    // 11 steps: t = 0 (initial conditions), then 0.01 .. 0.1; 5 or 6 requests of 6 columns.
    EXPECT_EQ(steps, 11) << name;
    EXPECT_EQ(static_cast<long>(out.tables.size()), requests) << name;
    EXPECT_EQ(n, requests * 6 * 11) << name;
    EXPECT_EQ(out.blocks, (std::vector<std::string>{"initialConditions_001", "dynamic_001"}));
    total += n;
    magnitudes += checkMagnitudes(out);
    fs::remove_all(dir);
  }
  EXPECT_EQ(total, (8 * 5 + 6) * 6 * 11);  // Prismatic_Case01 has six requests
  EXPECT_GT(magnitudes, 0);
  std::printf("[ values compared .out vs .req, nine joint cases: %ld; magnitudes checked: %ld ]\n",
              total, magnitudes);
}

TEST(TabularFile, PistonExampleAcrossPages) {
  const fs::path dir = scratch("out-piston");
  const fs::path example = fs::path(OPENMSS_SOURCE_DIR) / "examples" / "piston";
  fs::copy_file(example / "piston.adm", dir / "piston.adm");
  fs::copy_file(example / "piston.acf", dir / "piston.acf");
  const Result r = run("run piston.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const OutFile out = parseOut(dir / "piston.out");
  EXPECT_EQ(out.status, "Successful");
  long requests = 0, steps = 0;
  const long n = compareWithRequestFile(dir / "piston.req", out, &requests, &steps);
  EXPECT_GT(steps, static_cast<long>(2 * 50));  // more than two pages of 50 output times
  EXPECT_GT(out.pages, 2);
  EXPECT_EQ(n, requests * 6 * steps);
  const long magnitudes = checkMagnitudes(out);
  // REQUEST/11 DISPLACEMENT (F1 only), 12, 13 and the four FORCE requests 07..10 (F1 and F5).
  EXPECT_EQ(magnitudes, (1 + 2 * 2 + 4 * 2) * steps);
  std::printf("[ piston: %ld values compared .out vs .req over %d pages; %ld magnitudes ]\n", n,
              out.pages, magnitudes);
  // Two runs give the same bytes.
  fs::create_directories(dir / "again");
  fs::copy_file(dir / "piston.adm", dir / "again" / "piston.adm");
  fs::copy_file(dir / "piston.acf", dir / "again" / "piston.acf");
  ASSERT_EQ(run("run piston.acf --quiet", dir / "again").status, 0);
  EXPECT_EQ(slurp(dir / "piston.out"), slurp(dir / "again" / "piston.out"));
  fs::remove_all(dir);
}

TEST(TabularFile, AFailedRunKeepsEveryStepBeforeTheFailure) {
  // A force that grows without bound as t -> 0.55 s: the integrator gives up there; the .out
  // must hold t = 0 (initial conditions) and 0.1, ..., 0.5, as the .req does, and say so.
  const fs::path dir = scratch("out-fail");
  write(dir / "blow.adm",
        "pendulum whose force blows up\n"
        "PART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
        "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n"
        "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(0.55-TIME)\n"
        "REQUEST/1, DISPLACEMENT, I=20, J=10\nREQUEST/2, FORCE, I=20, J=10\n"
        "OUTPUT/REQSAVE\nEND\n");
  const Result r = run("run blow.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  const OutFile out = parseOut(dir / "blow.out");
  EXPECT_EQ(out.status, "Failed");
  EXPECT_EQ(out.blocks, (std::vector<std::string>{"initialConditions_001", "dynamic_001"}));
  long requests = 0, steps = 0;
  const long n = compareWithRequestFile(dir / "blow.req", out, &requests, &steps);
  EXPECT_EQ(steps, 6);
  EXPECT_EQ(n, 2 * 6 * 6);
  ASSERT_EQ(out.tables.at(2).rows.size(), 6u);
  // The SFORCE is the only force between markers 20 and 10 besides the joint (at 21, not 20):
  // its magnitude FM is the element's own 1/sqrt(0.55 - t) (1e-5 relative: six printed digits).
  for (int k = 1; k < 6; ++k) {
    const auto& row = out.tables.at(2).rows[static_cast<std::size_t>(k)];
    EXPECT_NEAR(row[0], 0.1 * k, 1e-12);
    const double f = 1.0 / std::sqrt(0.55 - row[0]);
    EXPECT_NEAR(row[1], f, 1e-5 * f);
  }
  EXPECT_EQ(checkMagnitudes(out), 6 * (1 + 2));
  fs::remove_all(dir);
}

TEST(TabularFile, NoprintWritesNoTabularFile) {
  const fs::path dir = scratch("out-noprint");
  write(dir / "p.adm",
        "pendulum\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
        "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n"
        "REQUEST/1, DISPLACEMENT, I=20, J=10\nOUTPUT/NOPRINT\nEND\n");
  const Result r = run("run p.adm --end 0.1 --dtout 0.05 --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "p.msg"));
  EXPECT_FALSE(fs::exists(dir / "p.out"));
  EXPECT_EQ(r.output.find("NOPRINT"), std::string::npos) << r.output;  // no warning
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss::output
