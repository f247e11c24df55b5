// Factors and solves one sparse matrix from a Matrix Market file with each sparse LU the
// project could use, and prints for each: analysis, factor, refactor and solve CPU times,
// the entries of L + U, the factorisation's flop count where the library reports it, and the
// scaled residual of a solve. Not a test: the tool behind docs/performance.md, "One
// factorisation of the pile's Newton matrix".
//
//   build/bench/openmss-factor-matrix [--prune] newton.mtx [repeats] [variant-substring]
//
// --prune drops the entries that are exactly zero first (as SparseLinearSolver does).
// The matrices are the scaled Newton matrices BdfIntegrator factors (docs/theory.md,
// "Sparse Newton matrix"); a right-hand side of A * (1, 2, ..., n)/n is solved.

#include <amd.h>
#include <cholmod.h>
#include <klu.h>
#include <umfpack.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Matrix = Eigen::SparseMatrix<double>;

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Matrix readMarket(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  if (line.find("coordinate") == std::string::npos || line.find("real") == std::string::npos)
    throw std::runtime_error(path + ": not a real coordinate Matrix Market file");
  while (std::getline(in, line) && !line.empty() && line[0] == '%') {
  }
  std::istringstream header(line);
  long rows = 0, cols = 0, entries = 0;
  header >> rows >> cols >> entries;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(entries));
  for (long k = 0; k < entries; ++k) {
    long i = 0, j = 0;
    double v = 0.0;
    in >> i >> j >> v;
    triplets.emplace_back(static_cast<int>(i - 1), static_cast<int>(j - 1), v);
  }
  Matrix a(rows, cols);
  a.setFromTriplets(triplets.begin(), triplets.end());
  a.makeCompressed();
  return a;
}

struct Result {
  double analyze = 0, factor = 0, refactor = -1, solve = 0;
  long factorNonZeros = 0;
  double flops = -1;
  double residual = 0;
};

// ||A x - b||_inf / (||A||_inf ||x||_inf + ||b||_inf)
double scaledResidual(const Matrix& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  double normA = 0;
  Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(a.rows());
  for (int c = 0; c < a.outerSize(); ++c)
    for (Matrix::InnerIterator e(a, c); e; ++e) rowSum(e.row()) += std::abs(e.value());
  normA = rowSum.maxCoeff();
  const Eigen::VectorXd r = a * x - b;
  return r.cwiseAbs().maxCoeff() / (normA * x.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff());
}

// The pattern of A + A^T (upper triangle, diagonal dropped) as a symmetric CHOLMOD matrix.
cholmod_sparse* symmetricPattern(int n, const int* ap, const int* ai, cholmod_common* cm) {
  std::vector<std::vector<int>> cols(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j)
    for (int p = ap[j]; p < ap[j + 1]; ++p) {
      const int i = ai[p];
      if (i < j) cols[j].push_back(i);
      if (i > j) cols[i].push_back(j);
    }
  size_t nnz = 0;
  for (auto& c : cols) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    nnz += c.size();
  }
  cholmod_sparse* s = cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_PATTERN, cm);
  int* sp = static_cast<int*>(s->p);
  int* si = static_cast<int*>(s->i);
  sp[0] = 0;
  for (int j = 0; j < n; ++j) {
    std::copy(cols[j].begin(), cols[j].end(), si + sp[j]);
    sp[j + 1] = sp[j] + static_cast<int>(cols[j].size());
  }
  return s;
}

// KLU's user ordering (common.ordering = 3): nested dissection of A + A^T, by METIS_NodeND
// (user_data null) or CHOLMOD's nested dissection (user_data non-null).
int nestedDissection(int n, int* ap, int* ai, int* perm, klu_common* common) {
  cholmod_common cm;
  cholmod_start(&cm);
  cholmod_sparse* s = symmetricPattern(n, ap, ai, &cm);
  int ok = 1;
  if (n < 3) {
    for (int i = 0; i < n; ++i) perm[i] = i;
  } else if (common->user_data == nullptr) {
    ok = cholmod_metis(s, nullptr, 0, 1, perm, &cm);
  } else {
    std::vector<int> cparent(static_cast<size_t>(n)), cmember(static_cast<size_t>(n));
    ok = cholmod_nested_dissection(s, nullptr, 0, perm, cparent.data(), cmember.data(), &cm) >= 0;
  }
  cholmod_free_sparse(&s, &cm);
  cholmod_finish(&cm);
  return ok ? 1 : 0;
}

Result runKlu(const Matrix& a, const Eigen::VectorXd& b, int ordering, bool btf, bool cholmodNd,
              int repeats) {
  const int n = static_cast<int>(a.cols());
  std::vector<int> ap(a.outerIndexPtr(), a.outerIndexPtr() + n + 1);
  std::vector<int> ai(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
  std::vector<double> ax(a.valuePtr(), a.valuePtr() + a.nonZeros());
  klu_common common;
  klu_defaults(&common);
  common.ordering = ordering;
  common.btf = btf ? 1 : 0;
  static int marker = 0;
  if (ordering == 3) {
    common.user_order = nestedDissection;
    common.user_data = cholmodNd ? &marker : nullptr;
  }
  Result r;
  double t0 = cpuSeconds();
  klu_symbolic* sym = klu_analyze(n, ap.data(), ai.data(), &common);
  r.analyze = cpuSeconds() - t0;
  if (!sym) return r;
  if (ordering == 0)
    std::printf(
        "  (KLU analysis predicts %.3g flops, %.0f entries of L + U; %d blocks, largest %d)\n",
        sym->est_flops, sym->lnz + sym->unz, sym->nblocks, sym->maxblock);
  klu_numeric* num = nullptr;
  r.factor = 1e300;
  for (int k = 0; k < repeats; ++k) {
    if (num) klu_free_numeric(&num, &common);
    t0 = cpuSeconds();
    num = klu_factor(ap.data(), ai.data(), ax.data(), sym, &common);
    r.factor = std::min(r.factor, cpuSeconds() - t0);
  }
  if (!num) return r;
  klu_flops(sym, num, &common);
  r.flops = common.flops;
  r.factorNonZeros = static_cast<long>(num->lnz) + num->unz;
  r.refactor = 1e300;
  for (int k = 0; k < repeats; ++k) {
    t0 = cpuSeconds();
    klu_refactor(ap.data(), ai.data(), ax.data(), sym, num, &common);
    r.refactor = std::min(r.refactor, cpuSeconds() - t0);
  }
  Eigen::VectorXd x = b;
  t0 = cpuSeconds();
  klu_solve(sym, num, n, 1, x.data(), &common);
  r.solve = cpuSeconds() - t0;
  r.residual = scaledResidual(a, x, b);
  klu_free_numeric(&num, &common);
  klu_free_symbolic(&sym, &common);
  return r;
}

Result runUmfpack(const Matrix& a, const Eigen::VectorXd& b, int ordering, int strategy,
                  int repeats) {
  const int n = static_cast<int>(a.cols());
  const int* ap = a.outerIndexPtr();
  const int* ai = a.innerIndexPtr();
  const double* ax = a.valuePtr();
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_di_defaults(control);
  control[UMFPACK_ORDERING] = ordering;
  control[UMFPACK_STRATEGY] = strategy;
  Result r;
  void* sym = nullptr;
  double t0 = cpuSeconds();
  if (umfpack_di_symbolic(n, n, ap, ai, ax, &sym, control, info) != UMFPACK_OK) return r;
  r.analyze = cpuSeconds() - t0;
  void* num = nullptr;
  r.factor = 1e300;
  for (int k = 0; k < repeats; ++k) {
    if (num) umfpack_di_free_numeric(&num);
    t0 = cpuSeconds();
    umfpack_di_numeric(ap, ai, ax, sym, &num, control, info);
    r.factor = std::min(r.factor, cpuSeconds() - t0);
  }
  r.flops = info[UMFPACK_FLOPS];
  r.factorNonZeros = static_cast<long>(info[UMFPACK_LNZ] + info[UMFPACK_UNZ] - n);
  Eigen::VectorXd x(n);
  t0 = cpuSeconds();
  umfpack_di_solve(UMFPACK_A, ap, ai, ax, x.data(), b.data(), num, control, info);
  r.solve = cpuSeconds() - t0;
  r.residual = scaledResidual(a, x, b);
  umfpack_di_free_numeric(&num);
  umfpack_di_free_symbolic(&sym);
  return r;
}

template <typename Ordering>
Result runEigenSparseLu(const Matrix& a, const Eigen::VectorXd& b, int repeats,
                        double pivotThreshold = 1.0) {
  Eigen::SparseLU<Matrix, Ordering> lu;
  lu.setPivotThreshold(pivotThreshold);
  Result r;
  double t0 = cpuSeconds();
  lu.analyzePattern(a);
  r.analyze = cpuSeconds() - t0;
  r.factor = 1e300;
  for (int k = 0; k < repeats; ++k) {
    t0 = cpuSeconds();
    lu.factorize(a);
    r.factor = std::min(r.factor, cpuSeconds() - t0);
  }
  if (lu.info() != Eigen::Success) return r;
  r.factorNonZeros = lu.nnzL() + lu.nnzU();
  t0 = cpuSeconds();
  const Eigen::VectorXd x = lu.solve(b);
  r.solve = cpuSeconds() - t0;
  r.residual = scaledResidual(a, x, b);
  return r;
}

// Eigen's ordering interface over METIS_NodeND of A + A^T (through CHOLMOD).
template <int Mode>  // 0 METIS, 1 CHOLMOD's nested dissection, 2 AMD (SuiteSparse)
struct SymmetricOrdering {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  template <typename MatrixType>
  void operator()(const MatrixType& a, PermutationType& perm) {
    const int n = static_cast<int>(a.cols());
    Matrix c = a;
    c.makeCompressed();
    std::vector<int> p(static_cast<size_t>(n));
    klu_common common;
    klu_defaults(&common);
    static int marker = 0;
    common.user_data = Mode == 1 ? &marker : nullptr;
    if (Mode == 2)
      amd_order(n, c.outerIndexPtr(), c.innerIndexPtr(), p.data(), nullptr, nullptr);
    else
      nestedDissection(n, c.outerIndexPtr(), c.innerIndexPtr(), p.data(), &common);
    // Eigen's permutation maps old index -> new position; METIS gives new -> old.
    perm.resize(n);
    for (int k = 0; k < n; ++k) perm.indices()(p[k]) = k;
  }
};

void print(const char* name, const Result& r) {
  std::printf("%-28s %9.4f %9.4f %9.4f %8.5f %11ld %10.3g %9.2e\n", name, r.analyze, r.factor,
              r.refactor, r.solve, r.factorNonZeros, r.flops, r.residual);
}

}  // namespace

int main(int argc, char** argv) {
  const bool prune = argc > 1 && std::string(argv[1]) == "--prune";
  if (prune) {
    --argc;
    ++argv;
  }
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s [--prune] matrix.mtx [repeats] [variant-substring]\n", argv[0]);
    return 2;
  }
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  const std::string only = argc > 3 ? argv[3] : "";
  Matrix a = readMarket(argv[1]);
  if (prune) {
    const long before = a.nonZeros();
    a.prune(0.0, 0.0);  // drop the entries that are exactly zero
    a.makeCompressed();
    std::printf("pruned %ld exact zeros of %ld entries\n", before - a.nonZeros(), before);
  }
  const int n = static_cast<int>(a.cols());
  const Eigen::VectorXd xTrue = Eigen::VectorXd::LinSpaced(n, 1.0 / n, 1.0);
  const Eigen::VectorXd b = a * xTrue;
  std::printf("%s: n = %d, nnz = %ld; CPU seconds (best of %d factorisations)\n", argv[1], n,
              static_cast<long>(a.nonZeros()), repeats);
  std::printf("%-28s %9s %9s %9s %8s %11s %10s %9s\n", "solver", "analyze", "factor", "refactor",
              "solve", "nnz(L+U)", "flops", "residual");
  const std::vector<std::pair<const char*, std::function<Result()>>> variants = {
      {"KLU AMD BTF (now)", [&] { return runKlu(a, b, 0, true, false, repeats); }},
      {"KLU AMD no-BTF", [&] { return runKlu(a, b, 0, false, false, repeats); }},
      {"KLU COLAMD BTF", [&] { return runKlu(a, b, 1, true, false, repeats); }},
      {"KLU METIS BTF", [&] { return runKlu(a, b, 3, true, false, repeats); }},
      {"KLU CHOLMOD-ND BTF", [&] { return runKlu(a, b, 3, true, true, repeats); }},
      {"UMFPACK default", [&] { return runUmfpack(a, b, UMFPACK_ORDERING_AMD, 0, repeats); }},
      {"UMFPACK METIS sym",
       [&] {
         return runUmfpack(a, b, UMFPACK_ORDERING_METIS, UMFPACK_STRATEGY_SYMMETRIC, repeats);
       }},
      {"Eigen SparseLU COLAMD",
       [&] { return runEigenSparseLu<Eigen::COLAMDOrdering<int>>(a, b, repeats); }},
      {"Eigen SparseLU Eigen-AMD",
       [&] { return runEigenSparseLu<Eigen::AMDOrdering<int>>(a, b, repeats, 1e-3); }},
      {"Eigen SparseLU METIS",
       [&] { return runEigenSparseLu<SymmetricOrdering<0>>(a, b, repeats, 1e-3); }},
      {"Eigen SparseLU CHOLMOD-ND",
       [&] { return runEigenSparseLu<SymmetricOrdering<1>>(a, b, repeats, 1e-3); }},
      {"Eigen SparseLU AMD (OpenMSS)",
       [&] { return runEigenSparseLu<SymmetricOrdering<2>>(a, b, repeats, 1e-3); }},
  };
  for (const auto& [name, run] : variants) {
    if (!only.empty() && std::string(name).find(only) == std::string::npos) continue;
    print(name, run());
    std::fflush(stdout);
  }
  return 0;
}
