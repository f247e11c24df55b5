#pragma once
// The graphics file (<prefix>.gra, OUTPUT/GRSAVE): the drawn GRAPHICS of a model, the markers
// they use, and every moving part's pose at each output time. ADAMS's layout is known only in
// part; the records OpenMSS writes, and what it chose where the layout is not documented, are
// in docs/output-files.md, "Graphics file (.gra)".

#include <Eigen/Dense>
#include <cstdio>
#include <string>
#include <vector>

#include "model/graphics.hpp"
#include "model/model.hpp"
#include "output/request_file.hpp"

namespace openmss::output {

// The pose of one moving part's body frame (CM origin, CM-marker axes) in ground.
struct GraphicsPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d angles = Eigen::Vector3d::Zero();  // body 3-1-3 PSI THETA PHI, radians
};

// The kind code of a graphic record (docs/output-files.md): CYLINDER 1, FRUSTUM 2, BOX 3,
// ELLIPSOID 4, OUTLINE 5, ARC 6, CIRCLE 7.
int graphicsKindCode(model::Graphic::Kind kind);

class GraphicsFileWriter {
 public:
  GraphicsFileWriter() = default;
  ~GraphicsFileWriter();
  GraphicsFileWriter(const GraphicsFileWriter&) = delete;
  GraphicsFileWriter& operator=(const GraphicsFileWriter&) = delete;

  // Creates the file and writes the header, part, graphic, marker and size records. `header`
  // is the request file's (title, units tag, stamp). False with *error set on failure.
  bool open(const std::string& path, const RequestFileHeader& header, const model::Model& model,
            const std::vector<model::Graphic>& graphics, std::string* error);
  // One output time: poses[k] is the k-th moving part's (Model::parts order, ground left out).
  // Flushed at once, so a failed run keeps every completed step.
  void writeStep(double time, const std::vector<GraphicsPose>& poses);
  void close();
  bool isOpen() const { return file_ != nullptr; }
  const std::string& error() const { return error_; }

 private:
  std::FILE* file_ = nullptr;
  std::size_t movingParts_ = 0;
  std::string error_;
};

}  // namespace openmss::output
