C     FORTRAN-77 CONTACT force laws for tests/contact/contact_user_law_test.cpp (gfortran:
C     cnfsub_, cffsub_, every argument by reference). CNFSUB and CFFSUB compute what Cnfsub
C     and Cffsub of contact_routines.c compute; PAR as documented there (PAR(1) is PAR[0]).
      SUBROUTINE CNFSUB(ID, TIME, PAR, NPAR, LOCI, NI, LOCJ, NJ, GAP,
     &                  GAPDOT, GAPDDT, AREA, DFLAG, IFLAG, VALUES)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), LOCI(3), NI(3), LOCJ(3), NJ(3)
      DOUBLE PRECISION GAP, GAPDOT, GAPDDT, AREA, VALUES(3), VEC(3)
      INTEGER IORD, ERR
      LOGICAL BAD
      VALUES(1) = 0.0D0
      IF (IFLAG .NE. 0) RETURN
      IORD = 0
      CALL IMPACT(GAP, GAPDOT, 0.0D0, PAR(1), PAR(2), PAR(3), PAR(4),
     &            IORD, VEC, ERR)
      BAD = ERR .NE. 0
      CALL ERRMES(BAD, 'IMPACT failed', ID, 'STOP')
      VALUES(1) = VEC(1)
      IF (.NOT. DFLAG) RETURN
      IF (NPAR .GT. 4) THEN
        IF (PAR(5) .NE. 0.0D0) RETURN
      END IF
      VALUES(2) = VEC(2)
      VALUES(3) = VEC(3)
      END

      SUBROUTINE CFFSUB(ID, TIME, PAR, NPAR, LOCI, LOCJ, X, XDOT,
     &                  NFORCE, AREA, DFLAG, IFLAG, VALUES)
      INTEGER ID, NPAR, IFLAG
      LOGICAL DFLAG
      DOUBLE PRECISION TIME, PAR(*), LOCI(3), LOCJ(3), X(3), XDOT(3)
      DOUBLE PRECISION NFORCE, AREA, VALUES(3)
      DOUBLE PRECISION S, A, DA, B, DB
      INTEGER ERR
      VALUES(1) = 0.0D0
      IF (IFLAG .NE. 0) RETURN
      S = XDOT(1)
      CALL STEP(S, -PAR(3), -1.0D0, PAR(3), 1.0D0, 0, A, ERR)
      CALL STEP(S, -PAR(3), -1.0D0, PAR(3), 1.0D0, 1, DA, ERR)
      CALL STEP(S, PAR(3), PAR(1), PAR(4), PAR(2), 0, B, ERR)
      CALL STEP(S, PAR(3), PAR(1), PAR(4), PAR(2), 1, DB, ERR)
      VALUES(1) = -NFORCE * A * B
      IF (.NOT. DFLAG) RETURN
      VALUES(2) = -NFORCE * (DA * B + A * DB)
      VALUES(3) = -A * B
      END
