C     FORTRAN-77 CONSUB for tests/user/consub_test.cpp (gfortran: consub_, every argument by
C     reference, each CHARACTER argument's length appended): the study of Consub in
C     consub_routines.c, "simulate to PAR(1), SFORCE/1 FUNCTION=PAR(3), simulate to PAR(2)",
C     output by DATOUT after each analysis.
      SUBROUTINE CONSUB(PAR, NPAR)
      INTEGER NPAR
      DOUBLE PRECISION PAR(*)
      INTEGER ISTAT
      CHARACTER*80 COMAND
      IF (NPAR .NE. 3) THEN
        CALL ERRMES(.TRUE., 'CONSUB needs USER(t1, t2, force)', 0,
     &              'STOP')
        RETURN
      END IF
      CALL ANALYS('DYNAMICS', 'first', 0.0D0, PAR(1), 1, ISTAT)
      IF (ISTAT .NE. 0) CALL ERRMES(.TRUE., 'the first ANALYS failed',
     &                              1, 'STOP')
      CALL DATOUT(ISTAT)
      WRITE (COMAND, '(A, ES25.17)') 'SFORCE/1, FUNCTION=', PAR(3)
      CALL MODIFY(COMAND, ISTAT)
      IF (ISTAT .NE. 0) CALL ERRMES(.TRUE., 'MODIFY failed', 2, 'STOP')
      CALL ANALYS('DYNAMICS', 'second', PAR(1), PAR(2), 0, ISTAT)
      IF (ISTAT .NE. 0) CALL ERRMES(.TRUE., 'the second ANALYS failed',
     &                              3, 'STOP')
      CALL DATOUT(ISTAT)
      END
