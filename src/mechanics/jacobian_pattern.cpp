#include "mechanics/jacobian_pattern.hpp"

#include <algorithm>
#include <atomic>
#include <numeric>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

// The columns one quantity depends on; `all` when some dependency could not be resolved.
struct Dependencies {
  std::vector<int> columns;
  bool all = false;
};

class PatternBuilder {
 public:
  // forceAndUserOnly: the rows of the force elements and user equations alone, unclaimed rows
  // left empty (forceAndUserPattern).
  PatternBuilder(const MultibodySystem& s, const std::vector<char>& contacts,
                 bool forceAndUserOnly = false, const std::vector<char>* skip = nullptr)
      : forceAndUserOnly_(forceAndUserOnly),
        skip_(skip),
        contacts_(contacts),
        s_(s),
        m_(s.model()),
        l_(s.layout()),
        rows_(static_cast<size_t>(l_.size())),
        claimed_(static_cast<size_t>(l_.size()), false),
        dense_(static_cast<size_t>(l_.size()), false) {}

  std::vector<std::vector<int>> build() {
    if (forceAndUserOnly_) {
      forceElements();
      userEquations();
      const int n = l_.size();
      for (int r = 0; r < n; ++r)
        if (dense_[r]) {
          rows_[r].resize(static_cast<size_t>(n));
          std::iota(rows_[r].begin(), rows_[r].end(), 0);
        }
      return std::move(rows_);
    }
    for (int b = 0; b < l_.bodies; ++b) bodyRows(b);
    forceElements();
    userEquations();
    constraints();
    // Rows nobody here knows how to fill (equations added to the residual without a pattern
    // rule) are dense: too full is slow, too sparse is wrong.
    const int n = l_.size();
    std::vector<int> every(static_cast<size_t>(n));
    std::iota(every.begin(), every.end(), 0);
    for (int r = 0; r < n; ++r)
      if (!claimed_[r] || dense_[r]) rows_[r] = every;
    return std::move(rows_);
  }

 private:
  int bodyOfMarker(int marker) const {
    if (marker < 0) return -1;
    return m_.parts[m_.markers[marker].part].body;
  }
  // Position, orientation, velocity and angular velocity of body b (what marker states read).
  void addKinematics(Dependencies& d, int b) const {
    if (b < 0) return;
    for (int c = 0; c < L::kMu; ++c) d.columns.push_back(l_.body(b) + c);
  }
  void addMarkerKinematics(Dependencies& d, int marker) const { addKinematics(d, bodyOfMarker(marker)); }
  // Position and orientation of body b (what constraint geometry reads).
  void addPose(Dependencies& d, int b) const {
    if (b < 0) return;
    for (int c = 0; c < L::kV; ++c) d.columns.push_back(l_.body(b) + c);
  }
  void addVariable(Dependencies& d, int variable) const { d.columns.push_back(l_.userAlg(variable)); }
  void addLinearOutput(Dependencies& d, int element) const {
    const model::LinearStateElement& e = m_.linearStates[element];
    for (int c = 0; c < e.a.rows(); ++c) d.columns.push_back(l_.userDiff(e.firstState + c));
    if (e.uArray >= 0)
      for (int v : m_.arrays[e.uArray].variables) addVariable(d, v);
  }

  // What a measure of a function expression reads (mechanics/measures.hpp, user_measures.hpp).
  void addMeasure(Dependencies& d, const model::Measure& ms) const {
    using K = model::MeasureKind;
    switch (ms.kind) {
      case K::Time:
        return;
      case K::VarVal:
        addVariable(d, ms.element);
        return;
      case K::Dif:
        d.columns.push_back(l_.userDiff(ms.element));
        return;
      case K::Dif1:
        d.columns.push_back(l_.userAlg(static_cast<int>(m_.variables.size()) + ms.element));
        return;
      case K::AryVal: {
        const model::DataArray& a = m_.arrays[ms.element];
        if (a.gse >= 0) {  // a GSE's state or output: one column (none for discrete states)
          const model::GeneralStateElement& e = m_.generalStates[a.gse];
          if (a.kind == model::DataArray::Kind::Y)
            d.columns.push_back(l_.userAlg(e.firstOutput + ms.component - 1));
          else if (!a.discrete)
            d.columns.push_back(l_.userDiff(e.firstState + ms.component - 1));
          return;
        }
        switch (a.kind) {
          case model::DataArray::Kind::X:
            d.columns.push_back(l_.userDiff(m_.linearStates[a.owner].firstState + ms.component - 1));
            return;
          case model::DataArray::Kind::U:
            addVariable(d, a.variables[ms.component - 1]);
            return;
          case model::DataArray::Kind::Y:
            addLinearOutput(d, a.owner);
            return;
          case model::DataArray::Kind::IC:
          case model::DataArray::Kind::Constants:
            return;
        }
        d.all = true;
        return;
      }
      case K::PinVal:
        addVariable(d, m_.pinputs[ms.element].variables[ms.component - 1]);
        return;
      case K::PouVal:
        addVariable(d, m_.poutputs[ms.element].variables[ms.component - 1]);
        return;
      // Marker measures read the states of the I, J and K markers' bodies.
      case K::DX: case K::DY: case K::DZ: case K::DM:
      case K::VX: case K::VY: case K::VZ: case K::VM: case K::VR:
      case K::WX: case K::WY: case K::WZ: case K::WM:
      case K::AX: case K::AY: case K::AZ:
      case K::PSI: case K::THETA: case K::PHI: case K::YAW: case K::PITCH: case K::ROLL:
      case K::Orient: case K::IncludedAngle:
        addMarkerKinematics(d, ms.i);
        addMarkerKinematics(d, ms.j);
        addMarkerKinematics(d, ms.k);
        addMarkerKinematics(d, ms.l);  // the derivative frame (-1 for ground: no columns)
        return;
      // Accelerations read y' of the same bodies' velocity entries: one column stands for
      // y_c and y'_c, so the marker kinematics columns cover them (dynamic_measures.hpp).
      case K::ACCX: case K::ACCY: case K::ACCZ: case K::ACCM:
      case K::WDTX: case K::WDTY: case K::WDTZ: case K::WDTM:
        addMarkerKinematics(d, ms.i);
        addMarkerKinematics(d, ms.j);
        addMarkerKinematics(d, ms.k);
        addMarkerKinematics(d, ms.l);  // the derivative frame (-1 for ground: no columns)
        return;
      case K::JointForce: case K::MotionForce: case K::JPrimForce:
        addReaction(d, ms);
        return;
      // Force read-backs (force_read_back.hpp): what the element's loads read, and the
      // resolution marker.
      case K::SForceForce: case K::SpringDamperForce: case K::BushingForce:
      case K::FieldForce: case K::BeamForce: case K::VForceForce: case K::VTorqueForce:
      case K::GForceForce:
        addElementReads(d, *forceElementOfMeasure(ms.kind, ms.element));
        addMarkerKinematics(d, ms.k);
        return;
      case K::NForceForce:
        addElementReads(d, {ForceElementKind::MultiPoint, ms.element});
        addMarkerKinematics(d, ms.k);
        return;
      case K::NetForce:
        addNetForce(d, ms);
        return;
      case K::FrictionOutput:  // FRICTION(id, index): what the friction's loads read
        addElementReads(d, {ForceElementKind::Friction, ms.element});
        return;
      default:
        // Any kind added later: not resolved here.
        d.all = true;
        return;
    }
  }
  // What force element e's loads read: the bodies of its markers and whatever its functions
  // read (read-backs of other elements included; the model builder refuses cycles, and a
  // chain longer than the element count is treated as unresolved all the same).
  void addElementReads(Dependencies& d, ForceElementRef e) const {
    const ForceElements& fe = s_.forceElements();
    if (++depth_ > static_cast<int>(fe.elements().size()) + 1) {
      d.all = true;
      --depth_;
      return;
    }
    addMarkerKinematics(d, fe.iMarker(e));
    addMarkerKinematics(d, fe.jMarker(e));
    switch (e.kind) {
      case ForceElementKind::SForce:
        addFunction(d, m_.sforces[e.index].function);
        break;
      case ForceElementKind::SpringDamper:
      case ForceElementKind::LinearField:
      case ForceElementKind::Contact:  // reads the poses of its two parts only
        break;
      case ForceElementKind::VectorForce: {
        const model::VectorForce& v = m_.vectorForces[e.index];
        addMarkerKinematics(d, v.rmMarker);
        for (const auto& component : v.components)
          if (component) addFunction(d, *component);
        break;
      }
      case ForceElementKind::Friction: {
        // The joint's reaction: its multipliers and the poses its equations read.
        model::Measure reaction;
        reaction.kind = model::MeasureKind::JointForce;
        reaction.element = m_.frictions[e.index].joint;
        addReaction(d, reaction);
        break;
      }
      case ForceElementKind::MultiPoint:
        for (int marker : m_.nforces[e.index].iMarkers) addMarkerKinematics(d, marker);
        break;
    }
    --depth_;
  }
  // FX..TM(i [,j] [,k]): the multipliers and marker poses of the constraint equations acting
  // on i (ForceElements::netForceTakes), the reads of the force elements acting on it, and the
  // bodies of i and k.
  void addNetForce(Dependencies& d, const model::Measure& ms) const {
    const ForceElements& fe = s_.forceElements();
    const auto& eqs = s_.constraints().equations();
    for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
      if (!fe.netForceTakes(eqs[k], ms.i, ms.j)) continue;
      d.columns.push_back(l_.lambda(k));
      for (int s = 0; s < eqs[k].markerCount(); ++s) addPose(d, bodyOfMarker(eqs[k].marker(s)));
    }
    for (const ForceElementRef& e : fe.elements()) {
      bool atJ = false;
      if (fe.netForceActs(e, ms.i, ms.j, &atJ)) addElementReads(d, e);
    }
    addMarkerKinematics(d, ms.i);
    addMarkerKinematics(d, ms.k);
  }
  // JOINT, JPRIM, MOTION reactions: -C^T lambda of the element's equations on one marker's
  // part, resolved in the k axes: their multipliers, the poses of every body those equations
  // read, and the resolution marker (constraintElementReaction in dynamic_measures.hpp).
  void addReaction(Dependencies& d, const model::Measure& ms) const {
    using K = model::MeasureKind;
    const auto& eqs = s_.constraints().equations();
    for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
      const ConstraintEquation& eq = eqs[k];
      const bool mine = ms.kind == K::JointForce    ? eq.joint == ms.element
                        : ms.kind == K::MotionForce ? eq.motion == ms.element
                                                    : eq.jprim == ms.element;
      if (!mine) continue;
      d.columns.push_back(l_.lambda(k));
      for (int s = 0; s < eq.markerCount(); ++s) addPose(d, bodyOfMarker(eq.marker(s)));
    }
    addMarkerKinematics(d, ms.k);
  }
  void addFunction(Dependencies& d, const model::BoundExpression& f) const {
    for (const model::Measure& ms : f.measures) addMeasure(d, ms);
  }

  void addRow(int row, const Dependencies& d) {
    claimed_[row] = true;
    if (d.all) dense_[row] = true;
    rows_[row].insert(rows_[row].end(), d.columns.begin(), d.columns.end());
  }
  void addEntry(int row, int column) {
    claimed_[row] = true;
    rows_[row].push_back(column);
  }
  // The force and moment balance rows of body b (nothing for ground).
  void addForceRows(int b, const Dependencies& d) {
    if (b < 0) return;
    for (int c = 0; c < 3; ++c) {
      addRow(l_.body(b) + L::kV + c, d);
      addRow(l_.body(b) + L::kW + c, d);
    }
  }

  // Kinematic equations, Newton-Euler left-hand sides and the normalisation of body b.
  void bodyRows(int b) {
    const int o = l_.body(b);
    for (int c = 0; c < 3; ++c) {
      addEntry(o + L::kR + c, o + L::kR + c);
      addEntry(o + L::kR + c, o + L::kV + c);
    }
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) addEntry(o + L::kE + r, o + L::kE + c);
      for (int c = 0; c < 3; ++c) addEntry(o + L::kE + r, o + L::kW + c);
      addEntry(o + L::kE + r, o + L::kMu);
    }
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        addEntry(o + L::kV + r, o + L::kV + c);
        addEntry(o + L::kW + r, o + L::kW + c);
      }
    for (int c = 0; c < 4; ++c) addEntry(o + L::kMu, o + L::kE + c);
  }

  // Every applied force element loads the bodies of its I and J (JFLOAT) markers with a value
  // that reads the bodies of all its markers and whatever its functions read; applying it reads
  // the loaded body's pose too.
  void forceElements() {
    const ForceElements& fe = s_.forceElements();
    for (size_t k = 0; k < fe.elements().size(); ++k) {
      const ForceElementRef& e = fe.elements()[k];
      if (skip_ != nullptr && !skip_->empty() && (*skip_)[k] != 0) continue;  // filled elsewhere
      // A CONTACT left out of a near-pair pattern (its bodies apart; theory §6c).
      if (e.kind == ForceElementKind::Contact && !contacts_.empty() && !contacts_[e.index])
        continue;
      Dependencies d;
      const int i = fe.iMarker(e), j = fe.jMarker(e);
      addElementReads(d, e);
      if (e.kind == ForceElementKind::MultiPoint)  // NFORCE loads every I marker's body
        for (int marker : m_.nforces[e.index].iMarkers) addForceRows(bodyOfMarker(marker), d);
      addForceRows(bodyOfMarker(i), d);
      addForceRows(bodyOfMarker(j), d);
    }
  }

  // VARIABLE, DIFF, LSE/TFSISO rows (mechanics/user_equations.hpp).
  void userEquations() {
    const int nv = static_cast<int>(m_.variables.size());
    for (int k = 0; k < nv; ++k) {
      Dependencies d;
      d.columns.push_back(l_.userAlg(k));
      addFunction(d, m_.variables[k].function);
      addRow(l_.userAlg(k), d);
    }
    for (int k = 0; k < static_cast<int>(m_.diffs.size()); ++k) {
      const int state = l_.userDiff(k), rate = l_.userAlg(nv + k);
      addEntry(state, state);
      addEntry(state, rate);
      Dependencies d;
      d.columns.push_back(rate);
      addFunction(d, m_.diffs[k].function);
      addRow(rate, d);
    }
    for (int el = 0; el < static_cast<int>(m_.linearStates.size()); ++el) {
      const model::LinearStateElement& e = m_.linearStates[el];
      Dependencies d;
      for (int c = 0; c < e.a.rows(); ++c) d.columns.push_back(l_.userDiff(e.firstState + c));
      if (e.uArray >= 0)
        for (int v : m_.arrays[e.uArray].variables) addVariable(d, v);
      for (int i = 0; i < e.a.rows(); ++i) addRow(l_.userDiff(e.firstState + i), d);
    }
    // GSE rows read its states and inputs (and an output row its own unknown).
    for (int el = 0; el < static_cast<int>(m_.generalStates.size()); ++el) {
      const model::GeneralStateElement& e = m_.generalStates[el];
      Dependencies d;
      for (int c = 0; c < e.ns; ++c) d.columns.push_back(l_.userDiff(e.firstState + c));
      if (e.uArray >= 0)
        for (int v : m_.arrays[e.uArray].variables) addVariable(d, v);
      for (int i = 0; i < e.ns; ++i) addRow(l_.userDiff(e.firstState + i), d);
      for (int j = 0; j < e.no; ++j) {
        Dependencies dj = d;
        dj.columns.push_back(l_.userAlg(e.firstOutput + j));
        addRow(l_.userAlg(e.firstOutput + j), dj);
      }
    }
  }

  // Constraint k: its row reads the poses of its markers' bodies (and its own multiplier while
  // inactive); its reaction C^T lambda loads those bodies' force rows with the same poses and
  // lambda_k. Activity may change between analyses: the pattern holds both forms.
  void constraints() {
    const auto& eqs = s_.constraints().equations();
    for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
      const ConstraintEquation& eq = eqs[k];
      Dependencies d;
      for (int side = 0; side < eq.markerCount(); ++side) addPose(d, bodyOfMarker(eq.marker(side)));
      using K = ConstraintEquation::Kind;
      switch (eq.kind) {
        case K::Point: case K::Dot: case K::Along: case K::MotionRotation:
        case K::MotionTranslation: case K::MotionAngle: case K::Convel: case K::RackPin:
        case K::Screw: case K::Coupled: case K::PointCurve: case K::CurveCurve:
          break;  // geometry of the marker frames (and a function of time)
        default:
          d.all = true;  // an equation kind whose reads are not known here
          break;
      }
      const int lambda = l_.lambda(k);
      addRow(lambda, d);
      addEntry(lambda, lambda);
      d.columns.push_back(lambda);
      for (int side = 0; side < eq.markerCount(); ++side) addForceRows(bodyOfMarker(eq.marker(side)), d);
    }
  }

  bool forceAndUserOnly_;
  const std::vector<char>* skip_;      // force elements left out (forceAndUserPattern)
  const std::vector<char>& contacts_;  // empty: every CONTACT
  mutable int depth_ = 0;  // nesting of addElementReads (read-backs of read-backs)
  const MultibodySystem& s_;
  const model::Model& m_;
  const StateLayout& l_;
  std::vector<std::vector<int>> rows_;
  std::vector<bool> claimed_, dense_;
};

}  // namespace

Eigen::SparseMatrix<double> JacobianPattern::matrix() const {
  Eigen::SparseMatrix<double> a(size, size);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(rowIndex.size());
  for (int c = 0; c < size; ++c)
    for (int k = columnStart[c]; k < columnStart[c + 1]; ++k) entries.emplace_back(rowIndex[k], c, 0.0);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

JacobianPattern patternFromRows(int size, std::vector<std::vector<int>> rows) {
  static std::atomic<std::uint64_t> patternsMade{0};
  JacobianPattern p;
  p.size = size;
  p.stamp = ++patternsMade;
  std::vector<int> count(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) {
    auto& row = rows[r];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    if (static_cast<int>(row.size()) == size) ++p.denseRows;
    for (int c : row) ++count[c + 1];
  }
  for (int c = 0; c < size; ++c) count[c + 1] += count[c];
  p.columnStart = count;
  p.rowIndex.resize(static_cast<size_t>(count[size]));
  std::vector<int> next(count.begin(), count.end() - 1);
  for (int r = 0; r < size; ++r)  // rows ascending, so each column's rows come out sorted
    for (int c : rows[r]) p.rowIndex[next[c]++] = r;
  colourColumns(p);
  return p;
}

JacobianPattern newtonMatrixPattern(const MultibodySystem& system,
                                    const std::vector<char>& contacts) {
  PatternBuilder builder(system, contacts);
  JacobianPattern p = patternFromRows(system.layout().size(), builder.build());
  p.contacts = contacts;
  return p;
}

JacobianPattern forceAndUserPattern(const MultibodySystem& system,
                                    const std::vector<char>& contacts,
                                    const std::vector<char>& skip) {
  PatternBuilder builder(system, contacts, true, &skip);
  JacobianPattern p = patternFromRows(system.layout().size(), builder.build());
  p.contacts = contacts;
  return p;
}

void colourColumns(JacobianPattern& p) {
  const int n = p.size;
  std::vector<int> colour(static_cast<size_t>(n), -1);
  int colours = 0;
  if (p.denseRows > 0) {
    // Every pair of columns shares a dense row: one colour per column.
    std::iota(colour.begin(), colour.end(), 0);
    colours = n;
  } else {
    // Row-wise copy of the pattern, to find the columns that share a row with column c.
    std::vector<int> rowStart(static_cast<size_t>(n) + 1, 0), columnIndex(p.rowIndex.size());
    for (int r : p.rowIndex) ++rowStart[r + 1];
    for (int r = 0; r < n; ++r) rowStart[r + 1] += rowStart[r];
    std::vector<int> next(rowStart.begin(), rowStart.end() - 1);
    for (int c = 0; c < n; ++c)
      for (int k = p.columnStart[c]; k < p.columnStart[c + 1]; ++k)
        columnIndex[next[p.rowIndex[k]]++] = c;
    // forbiddenBy[colour] == c marks a colour taken by a neighbour of column c.
    std::vector<int> forbiddenBy(static_cast<size_t>(n) + 1, -1);
    for (int c = 0; c < n; ++c) {
      for (int k = p.columnStart[c]; k < p.columnStart[c + 1]; ++k) {
        const int r = p.rowIndex[k];
        for (int q = rowStart[r]; q < rowStart[r + 1]; ++q)
          if (colour[columnIndex[q]] >= 0) forbiddenBy[colour[columnIndex[q]]] = c;
      }
      int chosen = 0;
      while (forbiddenBy[chosen] == c) ++chosen;
      colour[c] = chosen;
      colours = std::max(colours, chosen + 1);
    }
  }
  p.colourStart.assign(static_cast<size_t>(colours) + 1, 0);
  for (int c = 0; c < n; ++c) ++p.colourStart[colour[c] + 1];
  for (int k = 0; k < colours; ++k) p.colourStart[k + 1] += p.colourStart[k];
  p.colourColumns.resize(static_cast<size_t>(n));
  std::vector<int> next(p.colourStart.begin(), p.colourStart.end() - 1);
  for (int c = 0; c < n; ++c) p.colourColumns[next[colour[c]]++] = c;
}

void makeRowsDense(JacobianPattern& p, const std::vector<int>& denseRows) {
  const int n = p.size;
  std::vector<std::vector<int>> rows(static_cast<size_t>(n));
  for (int c = 0; c < n; ++c)
    for (int k = p.columnStart[c]; k < p.columnStart[c + 1]; ++k) rows[p.rowIndex[k]].push_back(c);
  for (int r : denseRows) {
    rows[r].resize(static_cast<size_t>(n));
    std::iota(rows[r].begin(), rows[r].end(), 0);
  }
  std::vector<char> contacts = std::move(p.contacts);
  p = patternFromRows(n, std::move(rows));
  p.contacts = std::move(contacts);
}

}  // namespace openmss::mechanics
