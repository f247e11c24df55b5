C     FORTRAN-77 UCON routine for tests/user/ucon_routine_test.cpp (gfortran: ucosub_, every
C     argument by reference, XMATRX(30, 30)): what Ucosub of ucon_routines.c computes, PAR as
C     documented there (PAR(1) here is PAR[0] there).
      SUBROUTINE UCOSUB(ID, TIME, Q, PAR, NPAR, IDRSEL, IFLAG, SCALAR,
     &                  ARRAY, XMATRX)
      INTEGER ID, NPAR, IDRSEL(3), IFLAG
      DOUBLE PRECISION TIME, Q(*), PAR(*), SCALAR, ARRAY(*)
      DOUBLE PRECISION XMATRX(30, 30)
      INTEGER LPARTS(6), LVARS(6), K, L, MODE, IA, IB
      DOUBLE PRECISION D(3), R, DELTA
      MODE = INT(PAR(1))
      IA = INT(PAR(2))
      IF (IFLAG .EQ. 3) THEN
        IF (MODE .EQ. 1) THEN
          LPARTS(1) = IA
          LVARS(1) = 13
          CALL UCOVAR(ID, 1, LPARTS, 1, LVARS)
        ELSE IF (MODE .EQ. 2) THEN
          DO 10 K = 1, 3
            LPARTS(K) = IA
            LVARS(K) = 10 + K
   10     CONTINUE
          CALL UCOVAR(ID, 3, LPARTS, 3, LVARS)
        ELSE
          IB = INT(PAR(3))
          DO 20 K = 1, 3
            LPARTS(K) = IA
            LPARTS(K + 3) = IB
            LVARS(K) = 310 + K
            LVARS(K + 3) = 310 + K
   20     CONTINUE
          CALL UCOVAR(ID, 6, LPARTS, 6, LVARS)
        END IF
      END IF
      IF (IFLAG .NE. 0) RETURN
      IF (MODE .EQ. 1) THEN
        IF (IDRSEL(1) .NE. 0) SCALAR = Q(1) - PAR(3)
        IF (IDRSEL(2) .NE. 0) ARRAY(1) = 1.0D0
      ELSE IF (MODE .EQ. 2) THEN
        D(1) = Q(1) - PAR(3)
        D(2) = Q(2) - PAR(4)
        D(3) = Q(3) - PAR(5)
        R = SQRT(D(1) * D(1) + D(2) * D(2) + D(3) * D(3))
        IF (IDRSEL(1) .NE. 0) SCALAR = R - PAR(6)
        IF (IDRSEL(2) .NE. 0) THEN
          DO 30 K = 1, 3
            ARRAY(K) = D(K) / R
   30     CONTINUE
        END IF
        IF (IDRSEL(3) .NE. 0) THEN
          DO 50 L = 1, 3
            DO 40 K = 1, 3
              DELTA = 0.0D0
              IF (K .EQ. L) DELTA = 1.0D0
              XMATRX(K, L) = (DELTA - D(K) * D(L) / (R * R)) / R
   40       CONTINUE
   50     CONTINUE
        END IF
      ELSE
        IF (IDRSEL(1) .NE. 0)
     &    SCALAR = Q(1) * Q(4) + Q(2) * Q(5) + Q(3) * Q(6)
        IF (IDRSEL(2) .NE. 0) THEN
          DO 60 K = 1, 3
            ARRAY(K) = Q(K + 3)
            ARRAY(K + 3) = Q(K)
   60     CONTINUE
        END IF
        IF (IDRSEL(3) .NE. 0) THEN
          DO 70 K = 1, 3
            XMATRX(K, K + 3) = 1.0D0
            XMATRX(K + 3, K) = 1.0D0
   70     CONTINUE
        END IF
      END IF
      END
