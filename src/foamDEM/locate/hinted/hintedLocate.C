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
    mainMapBuilt_(false),
    prevMainMapBuilt_(false),
    expectMain_(true),
    convex_(mesh.nCells(), true),
    nHintHits_(0),
    nNeighbourHits_(0),
    nTreeSearches_(0)
{
    // Each face's points against each face plane of the cell (the cell's
    // points through its faces: no cellPoints addressing kept on the mesh)
    const pointField& pts = mesh.points();
    const faceList& faces = mesh.faces();
    const vectorField& Cf = mesh.faceCentres();
    const vectorField& Sf = mesh.faceAreas();
    const labelList& own = mesh.faceOwner();
    label nConcave = 0;
    forAll(convex_, c)
    {
        const cell& cFaces = mesh.cells()[c];
        const scalar tol = 1e-6*Foam::cbrt(mag(mesh.cellVolumes()[c]));
        for (const label f : cFaces)
        {
            const vector n = (own[f] == c ? 1 : -1)*Sf[f]/mag(Sf[f]);
            for (const label g : cFaces)
            {
                if (g == f) continue;
                for (const label pt : faces[g])
                {
                    if (((pts[pt] - Cf[f]) & n) > tol)
                    {
                        convex_[c] = false;
                        break;
                    }
                }
                if (!convex_[c]) break;
            }
            if (!convex_[c]) break;
        }
        nConcave += !convex_[c];
    }
    if (debug)
    {
        Info<< "hintedLocate: " << nConcave << " of " << mesh.nCells()
            << " cells not convex (tested by tetrahedra)" << endl;
    }
}


bool Foam::foamDEM::hintedLocate::inCell(const point& p, label celli) const
{
    // Face-plane test: exact for convex cells and several times cheaper
    // than the tetrahedral one, which the octree search uses and which
    // cells that are not convex need
    return mesh_.pointInCell
    (
        p, celli,
        convex_[celli] ? polyMesh::FACE_PLANES : polyMesh::CELL_TETS
    );
}


Foam::label Foam::foamDEM::hintedLocate::hint(label id) const
{
    auto build = [](Map<label>& m, bool& built, const labelList& ids,
                    const labelList& cells)
    {
        if (built) return;
        m.clear();
        m.resize(2*ids.size());
        forAll(ids, i)
        {
            if (cells[i] >= 0) m.set(ids[i], cells[i]);
        }
        built = true;
    };

    auto iter = current_.cfind(id);
    if (iter.found()) return *iter;
    build(mainMap_, mainMapBuilt_, mainIds_, mainCells_);
    iter = mainMap_.cfind(id);
    if (iter.found()) return *iter;
    iter = previous_.cfind(id);
    if (iter.found()) return *iter;
    build(prevMainMap_, prevMainMapBuilt_, prevMainIds_, prevMainCells_);
    return prevMainMap_.lookup(id, -1);
}


void Foam::foamDEM::hintedLocate::beginStep()
{
    previous_.transfer(current_);
    current_.clear();
    prevMainIds_.transfer(mainIds_);
    prevMainCells_.transfer(mainCells_);
    std::swap(prevMainMap_, mainMap_);
    prevMainMapBuilt_ = mainMapBuilt_;
    mainMap_.clear();
    mainMapBuilt_ = false;
    expectMain_ = true;
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

    // The step's first call keeps its result by position (see mainIds_)
    const bool main = expectMain_;
    expectMain_ = false;
    if (main)
    {
        mainIds_.setSize(p.size());
        mainCells_.setSize(p.size());
        // Being filled: not a source of hints until the loop is done
        mainMap_.clear();
        mainMapBuilt_ = true;
    }

    forAll(p.cell, i)
    {
        const point& x = p.position[i];
        const label id = p.id[i];
        label hint = -1;
        if
        (
            main && i < prevMainIds_.size() && prevMainIds_[i] == id
         && prevMainCells_[i] >= 0
        )
        {
            hint = prevMainCells_[i];
        }
        else
        {
            hint = this->hint(id);
        }
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
            Pout<< "hintedLocate: particle " << id << " at " << x
                << " hint " << hint << " -> cell " << celli
                << (celli >= 0 ? " centre " : "")
                << (celli >= 0 ? mesh_.cellCentres()[celli] : point::zero) << endl;
        }
        if (main)
        {
            mainIds_[i] = id;
            mainCells_[i] = celli;
        }
        else if (celli >= 0)
        {
            current_.set(id, celli);
        }
        if (celli < 0)
        {
            ++nOutside;
        }
    }

    if (main)
    {
        mainMapBuilt_ = false;
    }

    if (debug)
    {
        Info<< "hintedLocate: hint " << nHintHits_ << ", neighbour "
            << nNeighbourHits_ << ", tree " << nTreeSearches_ << endl;
    }
    return nOutside;
}
