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
    // Face-plane test: exact for convex cells and several times cheaper
    // than the tetrahedral one, which the octree search keeps
    return mesh_.pointInCell(p, celli, polyMesh::FACE_PLANES);
}


Foam::label Foam::foamDEM::hintedLocate::hint(label id) const
{
    auto iter = current_.cfind(id);
    if (iter.found())
    {
        return *iter;
    }
    return previous_.lookup(id, -1);
}


void Foam::foamDEM::hintedLocate::beginStep()
{
    previous_.transfer(current_);
    current_.clear();
}


void Foam::foamDEM::hintedLocate::addRequirements(exchangePlan& plan) const
{
    plan.need(quantity::position, typeName);
    plan.need(quantity::id, typeName);
}


Foam::label Foam::foamDEM::hintedLocate::locate(particleData& p)
{
    const labelListList& cellCells = mesh_.cellCells();
    label nOutside = 0;

    forAll(p.cell, i)
    {
        const point& x = p.position[i];
        const label hint = this->hint(p.id[i]);
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
        if (debug > 1)
        {
            Pout<< "hintedLocate: particle " << p.id[i] << " at " << x
                << " hint " << hint << " -> cell " << celli
                << (celli >= 0 ? " centre " : "")
                << (celli >= 0 ? mesh_.cellCentres()[celli] : point::zero) << endl;
        }
        if (celli >= 0)
        {
            current_.set(p.id[i], celli);
        }
        else
        {
            ++nOutside;
        }
    }

    if (debug)
    {
        Info<< "hintedLocate: hint " << nHintHits_ << ", neighbour "
            << nNeighbourHits_ << ", tree " << nTreeSearches_ << endl;
    }
    return nOutside;
}
