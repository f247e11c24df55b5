#pragma once
// The CONTACT geometries read from GRAPHICS that are not solids of their own
// (docs/theory.md §6c): a closed planar OUTLINE as a bounded half-space ("OUTLINE floors"), and
// the 2-D geometries CIRCLE, ARC, POINT and CURVE of planar contact ("2-D contact").

#include <string>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/contact.hpp"
#include "model/model.hpp"

namespace openmss::model {

// OUTLINE=m1,...,mn: a closed polygon (the last marker the first again, or at its position) of
// markers on one part, all in one plane, read as a PLANE solid through m1's origin whose normal
// follows the winding (right-hand rule) and whose sideways limit is the polygon. False after a
// located diagnostic at `where` (the IGEOM/JGEOM value naming it).
bool readOutlineFloor(const language::Statement& g, const Model& model, const SourceLocation& where,
                      const std::string& subject, Diagnostics& diags, ContactSolid& out);

// CIRCLE (CM, RADIUS), ARC (CM, RADIUS, RANGLE), POINT (RM) or CURVE (CID, CRM) as a 2-D
// geometry of planar contact (theory §6c, "2-D contact"). False after a located diagnostic.
bool readPlanarGeometry(const language::Statement& g, const std::string& kind, const Model& model,
                        const SourceLocation& where, const std::string& subject, Diagnostics& diags,
                        ContactSolid& out);

// The 2-D rules of a CONTACT whose sides are read: IFLIP_GEOMETRY/JFLIP_GEOMETRY flip the named
// CIRCLE, ARC or CURVE geometries; 2-D and 3-D geometries do not mix; the pairs are ones the
// planar narrow phase covers; the geometries lie in one plane at the data set's configuration.
// False after one located diagnostic per fault.
bool checkPlanarContact(const language::Statement& s, Contact& c, const Model& model,
                        Diagnostics& diags);

}  // namespace openmss::model
