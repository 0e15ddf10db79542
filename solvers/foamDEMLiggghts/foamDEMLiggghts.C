/*---------------------------------------------------------------------------*\
Application
    foamDEMLiggghts

Description
    Runs a LIGGGHTS input script on its own, for the DEM-only stages of a
    case (packing, filling), so that a LIGGGHTS error reaches the user: the
    error line and the command it stopped in are written to stderr and to
    the log file, and every rank stops with a non-zero exit status. Takes
    the arguments of the liggghts executable:

        foamDEMLiggghts -in DEM/in.pack -log log.pack \
            -screen DEM/post/screen.pack -var bed ci
        mpirun -np 2 foamDEMLiggghts -in DEM/in.pack ...

    See src/foamDEM/demEngine/liggghts/liggghtsScript.H.

\*---------------------------------------------------------------------------*/

#include "liggghtsScript.H"

int main(int argc, char* argv[])
{
    return Foam::foamDEM::runLiggghtsScript(argc, argv);
}
