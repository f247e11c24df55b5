C     FORTRAN-77 COUPLER routines for tests/user/coupler_routine_test.cpp (gfortran: cousub_,
C     every argument by reference): what Cousub, Couxx and Couxx2 of coupler_routines.c
C     compute, PAR as documented there (PAR(1) here is PAR[0] there).
      SUBROUTINE COUSUB(ID, TIME, PAR, NPAR, DISP, NDISP, IFLAG, PHI)
      INTEGER ID, NPAR, NDISP, IFLAG
      DOUBLE PRECISION TIME, PAR(*), DISP(NDISP), PHI
      DOUBLE PRECISION S, G
      INTEGER K
      G = 0.0D0
      IF (NPAR .GE. 4) G = PAR(4)
      S = 0.0D0
      DO 10 K = 1, NDISP
        S = S + PAR(K) * DISP(K)
   10 CONTINUE
      IF (G .NE. 0.0D0) S = S + G * DISP(2) * DISP(2) * DISP(2)
      PHI = S
      END

      SUBROUTINE COUXX(ID, TIME, PAR, NPAR, DISP, NDISP, IFLAG, DFDA)
      INTEGER ID, NPAR, NDISP, IFLAG
      DOUBLE PRECISION TIME, PAR(*), DISP(NDISP), DFDA(NDISP)
      DOUBLE PRECISION G
      INTEGER K
      G = 0.0D0
      IF (NPAR .GE. 4) G = PAR(4)
      DO 10 K = 1, NDISP
        DFDA(K) = PAR(K)
   10 CONTINUE
      DFDA(2) = DFDA(2) + 3.0D0 * G * DISP(2) * DISP(2)
      END

      SUBROUTINE COUXX2(ID, TIME, PAR, NPAR, DISP, NDISP, IFLAG, D2FDA2)
      INTEGER ID, NPAR, NDISP, IFLAG
      DOUBLE PRECISION TIME, PAR(*), DISP(NDISP), D2FDA2(NDISP, NDISP)
      DOUBLE PRECISION G
      INTEGER K, L
      G = 0.0D0
      IF (NPAR .GE. 4) G = PAR(4)
      DO 20 L = 1, NDISP
        DO 10 K = 1, NDISP
          D2FDA2(K, L) = 0.0D0
   10   CONTINUE
   20 CONTINUE
      D2FDA2(2, 2) = 6.0D0 * G * DISP(2)
      END
