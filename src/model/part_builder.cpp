#include "model/part_builder.hpp"

#include <algorithm>
#include <string>

#include "common/rotation.hpp"
#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// Orientation from REULER or ZP/XP (in the reference frame), with the position origin; with
// USEXP (MARKER) x lies exactly toward XP and ZP only fixes the x-z plane (docs/language.md,
// "MARKER").
Eigen::Matrix3d orientationOf(StatementArguments& a, const char* zName, const char* xName,
                              const Eigen::Vector3d& origin, bool useX = false) {
  if (auto e = a.vec3("REULER")) return matrixFromEuler313((*e)(0), (*e)(1), (*e)(2));
  auto z = a.vec3(zName);
  auto x = a.vec3(xName);
  if (!z && !x) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d m;
  if (useX && x) {
    if (!matrixFromAxisPointsUseX(origin, z.value_or(origin), *x, z.has_value(), &m)) {
      a.error(a.statement().where,
              std::string("with USEXP the ") + xName + "/" + zName +
                  " points do not define a frame (a point coincides with the origin, or the z "
                  "point lies on the x axis)",
              "Move the points so that x is along the origin->XP line and ZP is off that line.");
      return Eigen::Matrix3d::Identity();
    }
    return m;
  }
  if (!matrixFromAxisPoints(origin, z.value_or(origin), x.value_or(origin), z.has_value(),
                            x.has_value(), &m)) {
    a.error(a.statement().where,
            std::string("the ") + zName + "/" + xName +
                " points do not define a frame (a point coincides with the origin, or the "
                "x point lies on the z axis)",
            "Move the points so that z is along the origin->ZP line and XP is off that line.");
    return Eigen::Matrix3d::Identity();
  }
  return m;
}

}  // namespace

void PartBuilder::readPart(const Statement& s, Diagnostics& diags) {
  StatementArguments a(s, diags);
  RawPart p;
  p.s = &s;
  if (!s.id) return;
  lastPartId_ = *s.id;
  p.qg = a.vec3("QG").value_or(Eigen::Vector3d::Zero());
  p.a = orientationOf(a, "ZG", "XG", p.qg);
  p.cm = a.id("CM");
  p.im = a.id("IM");
  if (const Argument* ip = s.find("IP")) {
    if (ip->values.size() != 3 && ip->values.size() != 6) {
      a.error(*ip, "IP needs 3 or 6 numbers", "Write IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz].");
    } else {
      for (int k = 0; k < 3; ++k) p.ip(k) = ip->values[k].number;
      if (ip->values.size() == 6)
        for (int k = 0; k < 3; ++k) p.products(k) = ip->values[3 + k].number;
    }
  }
  for (const char* unsupported : {"VM", "WM"})
    if (a.has(unsupported))
      a.error(*s.find(unsupported), std::string(unsupported) + " is not supported yet",
              "Remove it; initial velocities refer to the CM marker.");
  parts_.push_back(p);
}

void PartBuilder::readMarker(const Statement& s, Diagnostics& diags) {
  if (!s.id) return;
  StatementArguments a(s, diags);
  RawMarker m;
  m.s = &s;
  if (auto part = a.id("PART")) {
    m.part = *part;
  } else if (lastPartId_ != 0) {
    m.part = lastPartId_;  // ADAMS: PART defaults to the preceding PART statement
  } else {
    a.require("PART", "<part id>");
    return;
  }
  // FLOATING markers are read; only a JFLOAT argument may name one (markerReference).
  for (const char* unsupported : {"POINT_MASS", "FLEX_BODY", "NODE", "FE_PART", "NODE_LABEL"})
    if (a.has(unsupported))
      a.error(*s.find(unsupported), std::string(unsupported) + " markers are not supported yet",
              "Use a fixed marker on a rigid PART.");
  // USEXP qualifies XP; without XP (or with REULER, which sets the frame alone) it has no
  // meaning, which is said rather than ignored.
  const bool useX = a.has("USEXP");
  if (useX && (!a.has("XP") || a.has("REULER")))
    a.error(*s.find("USEXP"),
            a.has("REULER") ? "USEXP qualifies XP and ZP; REULER sets the frame alone"
                            : "USEXP makes XP the exact x axis, and no XP is given",
            a.has("REULER") ? "Remove USEXP (or give the frame by XP, ZP, USEXP instead)."
                            : "Give XP=x,y,z, or remove USEXP.");
  m.qp = a.vec3("QP").value_or(Eigen::Vector3d::Zero());
  m.a = orientationOf(a, "ZP", "XP", m.qp, useX);
  m.rm = a.id("RM");
  markers_.push_back(m);
}

void PartBuilder::build(const language::Dataset& dataset, Model& model, Diagnostics& diags) const {
  std::map<long, size_t> rawPartIndex;
  buildParts(dataset, model, diags, rawPartIndex);
  const GroundPoses poses = markerPoses(rawPartIndex, diags);
  bodyFrames(rawPartIndex, poses, model, diags);
  relativeMarkers(poses, model);
}

// Model::parts in statement order (the first of a repeated id), and the one ground part.
void PartBuilder::buildParts(const language::Dataset& dataset, Model& model, Diagnostics& diags,
                             std::map<long, size_t>& rawPartIndex) const {
  for (const RawPart& rp : parts_) {
    Part p;
    p.id = *rp.s->id;
    p.where = rp.s->where;
    p.ground = rp.s->has("GROUND");
    if (model.partIndex.count(p.id)) continue;  // the reader already warned about duplicates
    StatementArguments a(*rp.s, diags);
    if (!p.ground) {
      p.mass = a.real("MASS").value_or(0.0);
      const char* v[3] = {"VX", "VY", "VZ"};
      const char* w[3] = {"WX", "WY", "WZ"};
      for (int k = 0; k < 3; ++k) {
        if (auto x = a.real(v[k])) p.velocity[k] = *x;
        if (auto x = a.real(w[k])) p.angularVelocity[k] = *x;
      }
      // EXACT=X:Y:Z:PSI:THETA:PHI (the reader checked the words).
      if (const Argument* exact = rp.s->find("EXACT")) {
        static const char* kCoordinates[6] = {"X", "Y", "Z", "PSI", "THETA", "PHI"};
        for (const auto& value : exact->values)
          for (int k = 0; k < 6; ++k)
            if (value.text == kCoordinates[k]) p.exact[k] = true;
      }
    }
    rawPartIndex[p.id] = model.parts.size();
    model.partIndex[p.id] = static_cast<int>(model.parts.size());
    model.parts.push_back(p);
  }
  std::vector<int> grounds;
  for (size_t k = 0; k < model.parts.size(); ++k)
    if (model.parts[k].ground) grounds.push_back(static_cast<int>(k));
  if (grounds.empty()) {
    diags.error({dataset.file, 0, 0}, "", "the data set has no ground part",
                "Add PART/<id>, GROUND.");
    return;
  }
  model.groundPart = grounds[0];
  for (size_t k = 1; k < grounds.size(); ++k)
    diags.error(model.parts[grounds[k]].where, "PART/" + std::to_string(model.parts[grounds[k]].id),
                "a data set may have only one ground part; PART/" +
                    std::to_string(model.parts[grounds[0]].id) + " is ground already",
                "Remove GROUND from one of them.");
}

// Every marker's pose in ground at the data set's configuration: QP and the orientation are
// in the part's BCS (QG and its REULER or ZG/XG), or in the axes of an RM marker on that part.
PartBuilder::GroundPoses PartBuilder::markerPoses(const std::map<long, size_t>& rawPartIndex,
                                                  Diagnostics& diags) const {
  GroundPoses poses;
  for (const RawMarker& rm : markers_) {
    long mid = *rm.s->id;
    auto pit = rawPartIndex.find(rm.part);
    if (pit == rawPartIndex.end()) {
      const Argument* pa = rm.s->find("PART");
      diags.error(pa ? pa->where : rm.s->where, rm.s->subject(),
                  "PART/" + std::to_string(rm.part) + " does not exist",
                  "Use the id of a PART statement of this data set.");
      continue;
    }
    const RawPart& part = parts_[pit->second];
    Eigen::Vector3d qp = rm.qp;
    Eigen::Matrix3d a = rm.a;
    if (rm.rm) {
      // QP and orientation are given in the axes of a reference marker on the same part.
      auto found = std::find_if(markers_.begin(), markers_.end(),
                                [&](const RawMarker& o) { return *o.s->id == *rm.rm; });
      if (found == markers_.end() || found->part != rm.part || found->rm) {
        diags.error(rm.s->find("RM")->where, rm.s->subject(),
                    "RM=" + std::to_string(*rm.rm) +
                        " must be a marker on the same part positioned without RM",
                    "Give a marker of PART/" + std::to_string(rm.part) + ".");
        continue;
      }
      qp = found->qp + found->a * rm.qp;
      a = found->a * rm.a;
    }
    poses.position[mid] = part.qg + part.a * qp;
    poses.rotation[mid] = part.a * a;
    poses.part[mid] = rm.part;
  }
  return poses;
}

// Body frames: origin at the CM marker, its axes (the inertia axes); the inertia tensor about
// the CM in those axes, moved from the IM marker by the parallel-axis theorem.
void PartBuilder::bodyFrames(const std::map<long, size_t>& rawPartIndex, const GroundPoses& poses,
                             Model& model, Diagnostics& diags) const {
  auto onPart = [&](long marker, long part) {
    auto it = poses.part.find(marker);
    return it != poses.part.end() && it->second == part;
  };
  for (size_t k = 0; k < model.parts.size(); ++k) {
    Part& p = model.parts[k];
    const RawPart& rp = parts_[rawPartIndex.at(p.id)];
    const std::string subject = "PART/" + std::to_string(p.id);
    if (p.ground) {
      p.position = Eigen::Vector3d::Zero();
      p.orientation = Eigen::Matrix3d::Identity();
      continue;
    }
    // Without CM the part's BCS (QG and REULER or ZG/XG) is the centre-of-mass frame: ADAMS
    // makes CM optional, and a massless part needs none (docs/theory.md, "Parts as ADAMS
    // accepts them").
    if (rp.cm && !onPart(*rp.cm, p.id)) {
      diags.error(rp.s->find("CM")->where, subject,
                  "CM marker " + std::to_string(*rp.cm) + " is not a marker of this part",
                  "Give a MARKER with PART=" + std::to_string(p.id) + ".");
      continue;
    }
    if (p.mass < 0.0)
      diags.error(rp.s->find("MASS")->where, subject, "MASS must not be negative",
                  "Give MASS=<value> >= 0 (0 or no MASS: a massless part held by constraints).");
    p.position = rp.cm ? poses.position.at(*rp.cm) : rp.qg;
    p.orientation = rp.cm ? poses.rotation.at(*rp.cm) : rp.a;
    // Inertia about the IM marker (default CM) in IM axes; ADAMS products are +integrals.
    Eigen::Matrix3d iim;
    iim << rp.ip(0), -rp.products(0), -rp.products(1), -rp.products(0), rp.ip(1), -rp.products(2),
        -rp.products(1), -rp.products(2), rp.ip(2);
    Eigen::Matrix3d iG;  // in ground axes, about the CM
    if (rp.im && (!rp.cm || *rp.im != *rp.cm)) {
      if (!onPart(*rp.im, p.id)) {
        diags.error(rp.s->find("IM")->where, subject,
                    "IM marker " + std::to_string(*rp.im) + " is not a marker of this part",
                    "Give a MARKER with PART=" + std::to_string(p.id) + ".");
        continue;
      }
      const Eigen::Matrix3d& aim = poses.rotation.at(*rp.im);
      Eigen::Vector3d d = poses.position.at(*rp.im) - p.position;
      // Parallel-axis theorem back from the IM origin to the CM.
      iG = aim * iim * aim.transpose() -
           p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    } else {
      iG = p.orientation * iim * p.orientation.transpose();
    }
    p.inertia = p.orientation.transpose() * iG * p.orientation;
    // Zero principal moments are accepted (a point mass, a massless part, a slender rod): the
    // constraints must then hold the motions that carry no inertia, which the set-up analysis
    // checks. Moments that break the triangle inequality describe no rigid body, but ADAMS
    // runs them (the FAST certification data sets give IP=1e-3,1e-3,4418 for a nacelle) and
    // the equations need only a positive-semidefinite tensor: a warning. A negative moment
    // gives negative kinetic energy: an error. The tolerance is relative to the largest
    // moment: round-off of the parallel-axis transfer is ~1e-16 of it (docs/theory.md, "Parts
    // as ADAMS accepts them").
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(p.inertia);
    const Eigen::Vector3d pm = eig.eigenvalues();
    const double scale = std::max(pm.cwiseAbs().maxCoeff(), 1e-300);
    const SourceLocation& ipWhere = rp.s->find("IP") ? rp.s->find("IP")->where : p.where;
    if (pm.minCoeff() < -1e-9 * scale)
      diags.error(ipWhere, subject,
                  "the inertia tensor has a negative principal moment about the CM",
                  "Check IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz] (ADAMS products are +integrals) and, "
                  "with IM, the parallel-axis transfer to the CM.");
    else if (pm(0) + pm(1) < pm(2) * (1 - 1e-9))
      diags.warning(ipWhere, subject,
                    "the principal moments break the triangle inequality (no rigid body has "
                    "them); the run uses them as given, as ADAMS does",
                    "Check IP=Ixx,Iyy,Izz[,Ixy,Ixz,Iyz] if this is not deliberate.");
    if (pm.minCoeff() < 0.0) {
      // Round-off below zero: clip to the nearest positive-semidefinite tensor.
      const Eigen::Vector3d clipped = pm.cwiseMax(0.0);
      p.inertia = eig.eigenvectors() * clipped.asDiagonal() * eig.eigenvectors().transpose();
    }
    p.body = model.bodyCount();
    model.movingParts.push_back(static_cast<int>(k));
  }
}

// Markers relative to their body frames (the first of a repeated id).
void PartBuilder::relativeMarkers(const GroundPoses& poses, Model& model) const {
  for (const RawMarker& rm : markers_) {
    long mid = *rm.s->id;
    if (!poses.position.count(mid) || model.markerIndex.count(mid)) continue;
    Marker m;
    m.id = mid;
    m.where = rm.s->where;
    m.part = model.partIndex[rm.part];
    const Part& p = model.parts[m.part];
    m.position = p.orientation.transpose() * (poses.position.at(mid) - p.position);
    m.orientation = p.orientation.transpose() * poses.rotation.at(mid);
    m.floating = rm.s->has("FLOATING");
    model.markerIndex[mid] = static_cast<int>(model.markers.size());
    model.markers.push_back(m);
  }
}

int markerReference(const Model& model, const Statement& s, const char* name, Diagnostics& diags) {
  StatementArguments a(s, diags);
  auto idv = a.id(name);
  if (!idv) {
    if (!s.has(name)) a.require(name, "<marker id>");
    return -1;
  }
  auto it = model.markerIndex.find(*idv);
  if (it == model.markerIndex.end()) {
    a.error(*s.find(name),
            std::string(name) + "=" + std::to_string(*idv) + ": marker " + std::to_string(*idv) +
                " does not exist",
            "Use the id of a MARKER statement of this data set.");
    return -1;
  }
  if (model.markers[it->second].floating) {
    a.error(*s.find(name),
            std::string(name) + "=" + std::to_string(*idv) + ": marker " + std::to_string(*idv) +
                " is FLOATING; only JFLOAT of VFORCE, VTORQUE "
                "and GFORCE may name a floating marker",
            "Use a fixed marker (without FLOATING).");
    return -1;
  }
  return it->second;
}

}  // namespace openmss::model
