C     FORTRAN units for a FORTRAN SAVSUB/RELSUB (src/user/save_routines.cpp, docs/user-
C     subroutines.md "SAVSUB and RELSUB"): ADAMS hands those routines a FORTRAN unit already
C     connected to the save file. OpenMSS loads this module, which links the same gfortran
C     run-time library as the user's (one copy in the process), to connect the unit to a
C     scratch file before the call and to close it (flushing it) after.
      SUBROUTINE OMSSOP(IUNIT, PATH, IOK)
      INTEGER IUNIT, IOK
      CHARACTER*(*) PATH
      OPEN (UNIT=IUNIT, FILE=PATH, FORM='UNFORMATTED',
     &      ACCESS='SEQUENTIAL', STATUS='OLD', IOSTAT=IOK)
      END

      SUBROUTINE OMSSCL(IUNIT)
      INTEGER IUNIT
      CLOSE (UNIT=IUNIT)
      END
