C     The library of savsub_routines.c in FORTRAN 77 (gfortran), for tests/user/savsub_test.cpp:
C     REQSUB reports how many output steps it has been evaluated at (F2) and the time (F3);
C     SAVSUB writes the counter to the connected unit as one unformatted record, RELSUB reads it
C     back.
      SUBROUTINE REQSUB(ID, TIME, PAR, NPAR, IFLAG, RESULT)
      INTEGER ID, NPAR, IFLAG
      DOUBLE PRECISION TIME, PAR(*), RESULT(8)
      DOUBLE PRECISION COUNT
      COMMON /OMSCNT/ COUNT
      INTEGER K
      IF (IFLAG .EQ. 0) COUNT = COUNT + 1.0D0
      DO 10 K = 1, 8
        RESULT(K) = 0.0D0
   10 CONTINUE
      RESULT(2) = COUNT
      RESULT(3) = TIME
      END

      SUBROUTINE SAVSUB(IUNIT, IERR)
      INTEGER IUNIT, IERR
      DOUBLE PRECISION COUNT
      COMMON /OMSCNT/ COUNT
      WRITE (IUNIT, IOSTAT=IERR) COUNT
      END

      SUBROUTINE RELSUB(IUNIT, IERR)
      INTEGER IUNIT, IERR
      DOUBLE PRECISION COUNT, SAVED
      COMMON /OMSCNT/ COUNT
      READ (IUNIT, IOSTAT=IERR) SAVED
      IF (IERR .EQ. 0) COUNT = SAVED
      END
