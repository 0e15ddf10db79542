#include "hintedLocate.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(hintedLocate, 0);
    addToRunTimeSelectionTable(locateModel, hintedLocate, dictionary);
}
}


Foam::foamDEM::hintedLocate::hintedLocate
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    locateModel(mesh),
    search_(mesh, polyMesh::CELL_TETS),
    nHintHits_(0),
    nNeighbourHits_(0),
    nTreeSearches_(0)
{}


bool Foam::foamDEM::hintedLocate::inCell(const point& p, label celli) const
{
    return mesh_.pointInCell(p, celli, polyMesh::CELL_TETS);
}


void Foam::foamDEM::hintedLocate::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::position, typeName);
    plan.need(quantity::id, typeName);
}


Foam::label Foam::foamDEM::hintedLocate::locate(particleData& p)
{
    const labelListList& cellCells = mesh_.cellCells();
    Map<label> newHints(2*p.size());
    label nOutside = 0;

    forAll(p.cell, i)
    {
        const point& x = p.position[i];
        const label hint = hints_.lookup(p.id[i], -1);
        label celli = -1;

        if (hint >= 0 && inCell(x, hint))
        {
            celli = hint;
            ++nHintHits_;
        }
        else if (hint >= 0)
        {
            for (const label nbr : cellCells[hint])
            {
                if (inCell(x, nbr))
                {
                    celli = nbr;
                    ++nNeighbourHits_;
                    break;
                }
            }
        }
        if (celli < 0)
        {
            celli = search_.findCell(x, -1, true);
            ++nTreeSearches_;
        }

        p.cell[i] = celli;
        if (celli >= 0)
        {
            newHints.set(p.id[i], celli);
        }
        else
        {
            ++nOutside;
        }
    }

    hints_.transfer(newHints);

    if (debug)
    {
        Info<< "hintedLocate: hint " << nHintHits_ << ", neighbour "
            << nNeighbourHits_ << ", tree " << nTreeSearches_ << endl;
    }
    return nOutside;
}
