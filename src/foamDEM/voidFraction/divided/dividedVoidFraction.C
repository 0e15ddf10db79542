#include "dividedVoidFraction.H"
#include "shapeDescriptors.H"
#include "cyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "FixedList.H"
#include "addToRunTimeSelectionTable.H"
#include "primitivePatch.H"

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(dividedVoidFraction, 0);
    addToRunTimeSelectionTable(voidFractionModel, dividedVoidFraction, dictionary);
}
}


const Foam::label Foam::foamDEM::dividedVoidFraction::nSubVolumes;


namespace
{
    //- Root-mean-square radius of the shell a < r < b
    Foam::scalar rmsRadius(Foam::scalar a, Foam::scalar b)
    {
        using Foam::pow;
        return Foam::sqrt
        (
            0.6*(pow(b, 5) - pow(a, 5))/(pow(b, 3) - pow(a, 3))
        );
    }
}


// * * * * * * * * * * * * * * * Private functions  * * * * * * * * * * * * //

Foam::List<Foam::vector>
Foam::foamDEM::dividedVoidFraction::makeUnitPoints()
{
    const scalar phi = 0.5*(1 + sqrt(5.0));
    const scalar N = nSubVolumes;

    // Shell bounds: the core and the inner shell hold 1 and 12 sub-volumes
    const scalar rCore = cbrt(1/N);
    const scalar rInner = cbrt(13/N);
    const scalar r1 = rmsRadius(rCore, rInner);
    const scalar r2 = rmsRadius(rInner, 1);

    DynamicList<vector> pts(nSubVolumes);
    pts.append(vector::zero);

    const scalar sign[2] = {-1, 1};

    // Icosahedron vertices: cyclic permutations of (0, +-1, +-phi)
    for (const scalar s1 : sign)
    {
        for (const scalar s2 : sign)
        {
            for (const vector& v :
                {vector(0, s1, s2*phi), vector(s1, s2*phi, 0),
                 vector(s2*phi, 0, s1)})
            {
                pts.append(r1*v/mag(v));
            }
        }
    }

    // Dodecahedron vertices: (+-1, +-1, +-1) and cyclic permutations of
    // (0, +-1/phi, +-phi)
    for (const scalar s1 : sign)
    {
        for (const scalar s2 : sign)
        {
            for (const scalar s3 : sign)
            {
                const vector v(s1, s2, s3);
                pts.append(r2*v/mag(v));
            }
            for (const vector& v :
                {vector(0, s1/phi, s2*phi), vector(s1/phi, s2*phi, 0),
                 vector(s2*phi, 0, s1/phi)})
            {
                pts.append(r2*v/mag(v));
            }
        }
    }

    return List<vector>(std::move(pts));
}


bool Foam::foamDEM::dividedVoidFraction::pointsInsideCell
(
    const point& x,
    scalar r,
    label celli
) const
{
    return withinCell(x, r*maxPointRadius_, celli);
}


bool Foam::foamDEM::dividedVoidFraction::withinCell
(
    const point& x,
    scalar reach,
    label celli
) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& own = mesh_.faceOwner();

    for (const label facei : mesh_.cells()[celli])
    {
        const scalar sign = own[facei] == celli ? 1 : -1;
        if (sign*((Cf[facei] - x) & unitNormals_[facei]) < reach)
        {
            return false;
        }
    }
    return true;
}


Foam::label Foam::foamDEM::dividedVoidFraction::locatePoint
(
    const point& y0,
    label own,
    bool wallCell
) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& owner = mesh_.faceOwner();
    const labelList& neighbour = mesh_.faceNeighbour();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    point y = y0;
    label celli = own;
    for (label step = 0; step < maxWalkSteps_; ++step)
    {
        // The face whose plane y lies furthest outside of
        label exitFace = -1;
        scalar exitDistance = 0;
        for (const label facei : mesh_.cells()[celli])
        {
            const scalar d =
                (owner[facei] == celli ? 1 : -1)
               *((y - Cf[facei]) & unitNormals_[facei]);
            if (d > exitDistance)
            {
                exitDistance = d;
                exitFace = facei;
            }
        }
        if (exitFace < 0)
        {
            return celli;
        }

        ++nWalkSteps_;
        if (mesh_.isInternalFace(exitFace))
        {
            celli =
                owner[exitFace] == celli
              ? neighbour[exitFace]
              : owner[exitFace];
            continue;
        }

        const polyPatch& pp = patches[patches.whichPatch(exitFace)];
        if (isA<processorPolyPatch>(pp))
        {
            // On another processor
            ++nOutside_;
            return own;
        }
        if
        (
            isA<cyclicPolyPatch>(pp)
         && refCast<const cyclicPolyPatch>(pp).parallel()
        )
        {
            // Across a translational cyclic: shift, continue on the other side
            const polyPatch& nbr =
                refCast<const cyclicPolyPatch>(pp).neighbPatch();
            const label f = exitFace - pp.start();
            y += nbr.faceCentres()[f] - pp.faceCentres()[f];
            celli = nbr.faceCells()[f];
            ++nPeriodicCrossings_;
            continue;
        }
        // A wall or other boundary: outside, unless the domain is concave
        if (wallCell)
        {
            ++nAtWalls_;
            return celli;
        }
        if (beyondMesh(exitFace, exitDistance))
        {
            // What the octree search would find: no cell
            ++nBeyondMesh_;
            ++nOutside_;
            return own;
        }
        break;
    }

    ++nTreeSearches_;
    const label found = search_.findCell(y, -1, true);
    if (found >= 0)
    {
        return found;
    }
    ++nOutside_;
    return own;
}


bool Foam::foamDEM::dividedVoidFraction::beyondMesh(label f, scalar d) const
{
    // Only where the boundary's points are few enough to scan once per
    // face a walk leaves through (the scan is O(boundary points))
    if (boundaryPoints_.size() + mesh_.nCells() > 200000)
    {
        return false;
    }
    scalar& reach = boundaryReach_[f - mesh_.nInternalFaces()];
    if (reach < 0)
    {
        const pointField& pts = mesh_.points();
        const point& c = mesh_.faceCentres()[f];
        const vector& n = unitNormals_[f];
        reach = 0;
        for (const label pt : boundaryPoints_)
        {
            reach = max(reach, (pts[pt] - c) & n);
        }
        for (const point& cc : mesh_.cellCentres())
        {
            reach = max(reach, (cc - c) & n);
        }
    }
    // Ahead of every point of the mesh (with a margin for round-off)
    return
        d > reach + max(1e-9*Foam::sqrt(mag(mesh_.faceAreas()[f])), 10*SMALL);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::dividedVoidFraction::dividedVoidFraction
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    voidFractionModel(dict, mesh),
    unitPoints_(makeUnitPoints()),
    maxPointRadius_(max(mag(vectorField(unitPoints_)))),
    maxWalkSteps_(dict.getOrDefault<label>("maxWalkSteps", 100)),
    unitNormals_(mesh.faceAreas()/mag(mesh.faceAreas())),
    search_(mesh, polyMesh::CELL_TETS),
    boundaryReach_(mesh.nBoundaryFaces(), -1),
    boundaryPoints_
    (
        // The points of all boundary faces, as one patch's mesh points
        primitivePatch
        (
            SubList<face>
            (
                mesh.faces(), mesh.nBoundaryFaces(), mesh.nInternalFaces()
            ),
            mesh.points()
        ).meshPoints()
    ),
    nFastParticles_(0),
    nWalkSteps_(0),
    nTreeSearches_(0),
    nPeriodicCrossings_(0),
    nOutside_(0),
    nAtWalls_(0),
    nBeyondMesh_(0)
{
    namespace corr = ::foamDEM::correlations;
    const label nTarget = dict.getOrDefault<label>("shapeSubVolumes", 40);
    if (nTarget < 1)
    {
        FatalIOErrorInFunction(dict)
            << "shapeSubVolumes must be at least 1, got " << nTarget
            << exit(FatalIOError);
    }
    const Map<particleShape> shapes
    (
        readParticleShapes(dict.subOrEmptyDict("shapes"))
    );
    forAllConstIters(shapes, iter)
    {
        const particleShape& sh = iter.val();
        std::vector<corr::bodyPoint> pts;
        if (sh.kind == particleShape::kinds::plate)
        {
            pts = corr::subVolumePoints
            (
                corr::cuboid{sh.dim[0], sh.dim[1], sh.dim[2]}, nTarget
            );
        }
        else if (sh.kind == particleShape::kinds::spherocylinder)
        {
            pts = corr::subVolumePoints
            (
                corr::spherocylinder{sh.dim[0], sh.dim[1]}, nTarget
            );
        }
        shapePoints s{List<vector>(pts.size()), 0, Zero};
        forAll(s.points, k)
        {
            const vector b(pts[k][0], pts[k][1], pts[k][2]);
            s.points[k] = b;
            s.reach = max(s.reach, mag(b));
            s.extent = max(s.extent, cmptMag(b));
        }
        Info<< "    " << typeName << ": type " << iter.key() << " spread"
            << " over " << s.points.size() << " sub-volumes of its shape"
            << endl;
        shapes_.set(iter.key(), s);
    }
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

void Foam::foamDEM::dividedVoidFraction::addRequirements
(
    exchangePlan& plan
) const
{
    plan.need(quantity::position, typeName);
    plan.need(quantity::radius, typeName);
    if (shapes_.size())
    {
        plan.need(quantity::type, typeName);
        plan.need(quantity::orientation, typeName);
    }
}


void Foam::foamDEM::dividedVoidFraction::distribute
(
    const particleData& p,
    particleCellWeights& w
) const
{
    w.reset(p.size());

    FixedList<label, nSubVolumes> cells;
    FixedList<label, nSubVolumes> counts;

    forAll(p.cell, i)
    {
        const label own = p.cell[i];
        if (own < 0)
        {
            w.endParticle();
            continue;
        }

        const point& x = p.position[i];
        const scalar r = p.radius[i];

        const auto shaped =
            p.type.size() ? shapes_.cfind(p.type[i]) : shapes_.cend();
        if (shaped.found())
        {
            // The shape's points, turned by the particle's orientation
            const List<vector>& body = shaped.val().points;
            const vector& e = shaped.val().extent;
            const tensor& R = p.orientation[i];
            // Whole in its cell: the points lie in the box of their extents
            // (body frame), convex like the cell, so its corners decide
            bool whole = withinCell(x, shaped.val().reach, own);
            for (label c = 0; c < 8 && !whole; ++c)
            {
                const vector corner
                (
                    (c & 1 ? 1 : -1)*e.x(),
                    (c & 2 ? 1 : -1)*e.y(),
                    (c & 4 ? 1 : -1)*e.z()
                );
                if (!withinCell(x + (R & corner), 0, own)) break;
                whole = (c == 7);
            }
            if (whole)
            {
                ++nFastParticles_;
                w.append(own, 1);
                w.endParticle();
                continue;
            }
            DynamicList<label> shapeCells(8);
            DynamicList<label> shapeCounts(8);
            // Neighbouring points lie in the same or the next cell: each
            // walk starts from the previous point's cell
            label from = own;
            for (const vector& b : body)
            {
                const label celli = locatePoint(x + (R & b), from, true);
                from = celli;
                const label k = shapeCells.find(celli);
                if (k < 0)
                {
                    shapeCells.append(celli);
                    shapeCounts.append(1);
                }
                else
                {
                    ++shapeCounts[k];
                }
            }
            forAll(shapeCells, k)
            {
                w.append(shapeCells[k], scalar(shapeCounts[k])/body.size());
            }
            w.endParticle();
            continue;
        }

        if (pointsInsideCell(x, r, own))
        {
            ++nFastParticles_;
            w.append(own, 1);
            w.endParticle();
            continue;
        }

        // The core's point is the centre: in the particle's cell
        cells[0] = own;
        counts[0] = 1;
        label n = 1;
        for (label j = 1; j < nSubVolumes; ++j)
        {
            const label celli = locatePoint(x + r*unitPoints_[j], own);
            label k = 0;
            while (k < n && cells[k] != celli)
            {
                ++k;
            }
            if (k == n)
            {
                cells[n] = celli;
                counts[n] = 0;
                ++n;
            }
            ++counts[k];
        }
        for (label k = 0; k < n; ++k)
        {
            w.append(cells[k], scalar(counts[k])/nSubVolumes);
        }
        w.endParticle();
    }

    if (debug)
    {
        Info<< typeName << ": particles whole in their cell "
            << nFastParticles_ << ", walk steps " << nWalkSteps_
            << ", tree searches " << nTreeSearches_ << ", cyclic crossings "
            << nPeriodicCrossings_ << ", points outside to own cell "
            << nOutside_ << ", shape points beyond a wall to the wall cell "
            << nAtWalls_ << ", of the points outside, beyond the mesh's"
            << " reach past the wall they left by (no octree search) "
            << nBeyondMesh_ << endl;
    }
}
