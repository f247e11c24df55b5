#include "user/spline_reader.hpp"

#include <cstddef>
#include <cstring>

#include "user/element_call.hpp"
#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

using F77SplineRead = void(int* id, const char* file, const char* block, int* ierr,
                           std::size_t lfile, std::size_t lblock);

// The reader running on this thread: PUT_SPLINE stores into it.
struct Target {
  long id = 0;
  SplineValues* values = nullptr;
  int puts = 0;
};
thread_local Target target;

}  // namespace

bool readUserSpline(const ElementData& element, const std::string& file, const std::string& block,
                    const RoutineName& routine, const std::string& baseDirectory, SplineValues& out,
                    std::string& error) {
  ResolvedRoutine resolved;
  if (!resolveRoutine("SPLINE_READ", routine, baseDirectory, resolved, error)) return false;
  const PlainRoutine r("SPLINE_READ", element.subject, std::move(resolved), element.data);
  const Target saved = target;
  target = {element.id, &out, 0};
  int ierr = 0;
  const bool ran = r.call(0.0, [&] {
    int id = static_cast<int>(element.id);
    if (r.fortran()) {
      r.function<F77SplineRead>()(&id, file.c_str(), block.c_str(), &ierr, file.size(),
                                  block.size());
    } else {
      const sAdamsSpline s{id, file.c_str(), block.c_str()};
      r.function<adams_c_Spline_read>()(&s, &ierr);
    }
  });
  const int puts = target.puts;
  target = saved;
  if (!ran) {
    error = r.fatalError();
    return false;
  }
  if (ierr != 0) {
    error = r.who() + " returned IERR = " + std::to_string(ierr) + " for FILE=" + file +
            ", BLOCK=" + block;
    return false;
  }
  if (puts == 0) {
    error = r.who() + " returned without storing the data (PUT_SPLINE was not called)";
    return false;
  }
  return true;
}

}  // namespace openmss::user

void openmss::user::detail::anchorSplineReader() {}

extern "C" {

// PUT_SPLINE: nx x values, nz z values (nz <= 1: one curve, z = 0), and y curve by curve:
// y[j * nx + i] is curve j at x[i] (docs/user-subroutines.md). Only inside SPLINE_READ, for
// its own SPLINE id; else *errflg = 1.
void c_put_spline(int id, int nxvals, int nzvals, const double* xvals, const double* yvals,
                  const double* zvals, int* errflg) {
  using openmss::user::target;
  *errflg = 1;
  if (!target.values || id != target.id || nxvals < 1) return;
  const int nz = nzvals < 1 ? 1 : nzvals;
  openmss::user::SplineValues& v = *target.values;
  v.x.assign(xvals, xvals + nxvals);
  v.z.assign(static_cast<std::size_t>(nz), 0.0);
  if (nzvals >= 1 && zvals) v.z.assign(zvals, zvals + nzvals);
  v.curves.clear();
  for (int j = 0; j < nz; ++j)
    v.curves.emplace_back(yvals + static_cast<std::ptrdiff_t>(j) * nxvals,
                          yvals + static_cast<std::ptrdiff_t>(j + 1) * nxvals);
  ++target.puts;
  *errflg = 0;
}

void put_spline_(const int* id, const int* nxvals, const int* nzvals, const double* xvals,
                 const double* yvals, const double* zvals, int* errflg) {
  c_put_spline(*id, *nxvals, *nzvals, xvals, yvals, zvals, errflg);
}

}  // extern "C"
