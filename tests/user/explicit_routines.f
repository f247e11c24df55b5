C     FORTRAN-77 routines with explicit arguments for tests/user/field_routine_test.cpp
C     (gfortran: fiesub_, every argument by reference). FIESUB computes what Fiesub of
C     explicit_routines.c computes; PAR as documented there (PAR(1) here is PAR[0] there).
      SUBROUTINE FIESUB(ID, TIME, PAR, NPAR, DISP, VELO, DFLAG, IFLAG,
     &                  FIELD, DFDDIS, DFDVEL)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), DISP(6), VELO(6), FIELD(6)
      DOUBLE PRECISION DFDDIS(6,6), DFDVEL(6,6)
      DOUBLE PRECISION K, C, G, S
      INTEGER R, J
      G = 0.0D0
      IF (NPAR .GE. 28) G = PAR(28)
      DO 20 R = 1, 6
        S = PAR(20 + R)
        DO 10 J = 1, 6
          K = PAR(7)
          C = PAR(14)
          IF (R .EQ. J) K = PAR(R)
          IF (R .EQ. J) C = PAR(7 + R)
          IF (K .NE. 0.0D0) S = S - K * (DISP(J) - PAR(14 + J))
          IF (C .NE. 0.0D0) S = S - C * VELO(J)
   10   CONTINUE
        IF (G .NE. 0.0D0) S = S - G * DISP(R) * DISP(R) * DISP(R)
        FIELD(R) = S
   20 CONTINUE
      IF (.NOT. DFLAG .OR. PAR(27) .EQ. 0.0D0) RETURN
      DO 40 R = 1, 6
        DO 30 J = 1, 6
          DFDDIS(R, J) = -PAR(7)
          DFDVEL(R, J) = -PAR(14)
          IF (R .EQ. J) DFDDIS(R, J) = -PAR(R) - 3.0D0 * G * DISP(R)**2
          IF (R .EQ. J) DFDVEL(R, J) = -PAR(7 + R)
   30   CONTINUE
   40 CONTINUE
      END

C     CURSUB: the circle of Cursub in explicit_routines.c, radius PAR(1).
      SUBROUTINE CURSUB(ID, PAR, NPAR, ALPHA, IORD, IFLAG, VALUES)
      INTEGER ID, NPAR, IORD, IFLAG
      DOUBLE PRECISION PAR(*), ALPHA, VALUES(3)
      DOUBLE PRECISION R, S, C
      R = PAR(1)
      S = SIN(ALPHA)
      C = COS(ALPHA)
      VALUES(3) = 0.0D0
      IF (IORD .EQ. 0) THEN
        VALUES(1) = R * S
        VALUES(2) = -R * C
      ELSE IF (IORD .EQ. 1) THEN
        VALUES(1) = R * C
        VALUES(2) = R * S
      ELSE
        VALUES(1) = -R * S
        VALUES(2) = R * C
      END IF
      END

C     SPLINE_READ: what Spline_read of explicit_routines.c does, with FORTRAN I/O.
      SUBROUTINE SPLINE_READ(ID, FILNAM, BLKNAM, IERR)
      INTEGER ID, IERR
      CHARACTER*(*) FILNAM, BLKNAM
      DOUBLE PRECISION X(100), Y(100), Z(1), S
      INTEGER N, IOS, ERR
      IERR = 1
      S = 1.0D0
      IF (BLKNAM .EQ. 'DOUBLE') S = 2.0D0
      OPEN(UNIT=41, FILE=FILNAM, STATUS='OLD', IOSTAT=IOS)
      IF (IOS .NE. 0) RETURN
      N = 0
   10 READ(41, *, IOSTAT=IOS) X(N + 1), Y(N + 1)
      IF (IOS .EQ. 0) THEN
        Y(N + 1) = S * Y(N + 1)
        N = N + 1
        IF (N .LT. 100) GOTO 10
      END IF
      CLOSE(41)
      Z(1) = 0.0D0
      CALL PUT_SPLINE(ID, N, 1, X, Y, Z, ERR)
      IERR = ERR
      END

C     GSESUB (old GSE interface): the system of Gsesub in explicit_routines.c, without the
C     partial routines (the solver differences it).
      SUBROUTINE GSESUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, NSTATE,
     &                  STATES, NINPUT, INPUT, NOUTPT, STATED, OUTPUT)
      INTEGER ID, NPAR, IFLAG, NSTATE, NINPUT, NOUTPT
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), STATES(*), INPUT(*), STATED(*)
      DOUBLE PRECISION OUTPUT(*), W, Z
      W = PAR(1)
      Z = PAR(2)
      STATED(1) = STATES(2)
      STATED(2) = W * W * (INPUT(1) - STATES(1))
     &            - 2.0D0 * Z * W * STATES(2)
      OUTPUT(1) = STATES(1)
      END
