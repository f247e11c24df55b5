C     FORTRAN-77 evaluation subroutines for tests/user/element_routine_test.cpp (gfortran:
C     symbols sfosub_, varsub_, gfosub_, reqsub_; every argument by reference). They compute
C     what the C routines of element_routines.c compute, through the FORTRAN utilities
C     (SYSFNC, SYSARY, SYSPAR, ERRMES, ADAMS_NEEDS_PARTIALS).
C
C     Spring-damper F = -k (DZ(i,j) - L) - c VZ(i,j); PAR = k, c, L, i, j, partials.
      SUBROUTINE SFOSUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, VALUE)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), VALUE
      DOUBLE PRECISION SPRING
      VALUE = SPRING(PAR, NPAR)
      END

      DOUBLE PRECISION FUNCTION SPRING(PAR, NPAR)
      INTEGER NPAR
      DOUBLE PRECISION PAR(*)
      INTEGER IPAR(2), N
      LOGICAL ERRFLG, NEED
      DOUBLE PRECISION DISP(3), VEL(3), DDZ(3), DVZ(3)
      INTEGER K
      IPAR(1) = NINT(PAR(4))
      IPAR(2) = NINT(PAR(5))
C     TDISP, not DISP: the 3-1-3 angles DISP adds have no partials at zero rotation.
      CALL SYSARY('TDISP', IPAR, 2, DISP, N, ERRFLG)
      CALL ERRMES(ERRFLG, 'SYSARY TDISP failed', IPAR(1), 'STOP')
      CALL SYSARY('TVEL', IPAR, 2, VEL, N, ERRFLG)
      CALL ERRMES(ERRFLG, 'SYSARY TVEL failed', IPAR(1), 'STOP')
      NEED = .FALSE.
      IF (NPAR .GE. 6) THEN
        IF (PAR(6) .NE. 0.0D0) CALL ADAMS_NEEDS_PARTIALS(NEED)
      END IF
      IF (NEED) THEN
        DO 10 K = 1, 3
          DDZ(K) = 0.0D0
          DVZ(K) = 0.0D0
   10   CONTINUE
        DDZ(3) = -PAR(1)
        DVZ(3) = -PAR(2)
        CALL SYSPAR('TDISP', IPAR, 2, DDZ, 3, ERRFLG)
        CALL SYSPAR('TVEL', IPAR, 2, DVZ, 3, ERRFLG)
      END IF
      SPRING = -PAR(1) * (DISP(3) - PAR(3)) - PAR(2) * VEL(3)
      END

C     The same spring as the third of six GFORCE components.
      SUBROUTINE GFOSUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, RESULT)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), RESULT(6)
      DOUBLE PRECISION SPRING
      INTEGER K
      DO 20 K = 1, 6
        RESULT(K) = 0.0D0
   20 CONTINUE
      RESULT(3) = SPRING(PAR, NPAR)
      END

C     V = a DZ(i,j) + b TIME; PAR = a, b, i, j.
      SUBROUTINE VARSUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, VALUE)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), VALUE
      INTEGER IPAR(2)
      LOGICAL ERRFLG
      DOUBLE PRECISION DZ
      IPAR(1) = NINT(PAR(3))
      IPAR(2) = NINT(PAR(4))
      CALL SYSFNC('DZ', IPAR, 2, DZ, ERRFLG)
      CALL ERRMES(ERRFLG, 'SYSFNC DZ failed', ID, 'STOP')
      VALUE = PAR(1) * DZ + PAR(2) * TIME
      END

C     F2..F4 = DZ, VZ, VARVAL(v); F6..F8 = DIF(d), TIME, DZ VZ; PAR = i, j, v, d.
      SUBROUTINE REQSUB(ID, TIME, PAR, NPAR, IFLAG, RESULT)
      INTEGER ID, NPAR, IFLAG
      DOUBLE PRECISION TIME, PAR(*), RESULT(8)
      INTEGER IPAR(2)
      LOGICAL ERRFLG
      DOUBLE PRECISION DZ, VZ
      IPAR(1) = NINT(PAR(1))
      IPAR(2) = NINT(PAR(2))
      CALL SYSFNC('DZ', IPAR, 2, DZ, ERRFLG)
      CALL SYSFNC('VZ', IPAR, 2, VZ, ERRFLG)
      RESULT(1) = 0.0D0
      RESULT(2) = DZ
      RESULT(3) = VZ
      IPAR(1) = NINT(PAR(3))
      CALL SYSFNC('VARVAL', IPAR, 1, RESULT(4), ERRFLG)
      RESULT(5) = 0.0D0
      IPAR(1) = NINT(PAR(4))
      CALL SYSFNC('DIF', IPAR, 1, RESULT(6), ERRFLG)
      RESULT(7) = TIME
      RESULT(8) = DZ * VZ
      END

C     USRMES from a REQSUB (ROUTINE=lib::Usrreq): one message printed (MSGFLG .TRUE.), one not;
C     RESULT(2) = TIME. The strings reach USRMES with gfortran's hidden lengths.
      SUBROUTINE USRREQ(ID, TIME, PAR, NPAR, IFLAG, RESULT)
      INTEGER ID, NPAR, IFLAG, K
      DOUBLE PRECISION TIME, PAR(*), RESULT(8)
      DO 10 K = 1, 8
        RESULT(K) = 0.0D0
   10 CONTINUE
      RESULT(2) = TIME
      IF (IFLAG .NE. 0) RETURN
      CALL USRMES(.TRUE., 'FORTRAN REQSUB says hello', ID, 'WARNING')
      CALL USRMES(.FALSE., 'never printed', ID, 'INFO')
      END
