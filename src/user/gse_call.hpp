#pragma once
// The utility subroutines as a running GSE routine sees them (loaded_gse_routines.cpp);
// utility_subroutines.cpp dispatches to them while a GSE routine runs. Internal to src/user.

namespace openmss::user::detail {

bool gseCallActive();
void gseSysary(const char* fncnam, const int* ipar, int nsize, double* states, int* nstates,
               int* errflg);
void gseSysfnc(const char* fncnam, const int* ipar, int nsize, double* state, int* errflg);
void gseSyspar(const char* fncnam, const int* ipar, int nsize, const double* partials, int npartl,
               int* errflg);
void gseNeedsPartials(int* evalJac);
int gseNs();
int gseNd();
int gseNi();
int gseNo();
void gseX(double* x, int ns);
void gseXd(double* xd, int nd);
void gseU(double* u, int ni);
void gseTimget(double* time);
void gseErrmes(int errflg, const char* mesage, int id, const char* endflg);

}  // namespace openmss::user::detail
