/*---------------------------------------------------------------------------*\
Application
    testVoidFraction

Description
    Tests of the void fraction models (centre, divided, smoothed) and of
    particleAveraging on a real mesh. Particles are made by hand with a
    fixed seed: random ones (some outside the mesh), on cell faces, mesh
    edges and mesh points, straddling walls, larger than cells, and a dense
    cluster that must be clipped. Checks, per model:
      - exchange plan: the model asks for what it uses;
      - bounds: alphaMin <= eps <= 1 in cells and on patches;
      - conservation: sum_c (1 - eps_c) V_c = sum_i V_i - lost, 1e-12
        relative, and nothing clipped or lost where nothing may be;
      - cell weights: per particle in the mesh they sum to 1, none for
        particles outside; particle eps = sum_c w_ic eps_c;
      - averaging: a uniform particle velocity comes back exactly in the
        cells with particles (0 elsewhere for unsmoothed models), and the
        average conserves the particles' momentum sum_i V_i v_i;
      - smoothed: no new maxima, no negative values.
    Suites (-suite): box (sheared, graded mesh with walls), periodic (cyclic
    in x: conservation and spreading across the periodic plane), parallel
    (the box decomposed; processor patches), badInput (FatalIOError on
    inconsistent keys), snapped (a snappyHexMesh mesh, the
    cohesiveBedEvacuation tutorial's: hinted locate against findCell with
    tetrahedra at 20 000 random points, then the box checks), concave
    (an L-shaped duct: divided's sub-volume points past its re-entrant
    edge against findCell), shapes,
    interpolation (couplingKernel cellPoint: a linear U and eps read
    exactly at the particles on a uniform mesh, serial and decomposed; the
    cell kernel's read off it; the implicit coupling's explicit share
    balancing the reaction; the correction refused).

    Exit code 1 when any check fails; every check prints PASS or FAIL.

Usage
    testVoidFraction -case <case> -suite box|periodic|parallel|badInput [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "Random.H"
#include "OStringStream.H"
#include "processorPolyPatch.H"
#include "clockTime.H"
#include <algorithm>

#include "voidFractionModel.H"
#include "smoothedVoidFraction.H"
#include "dividedVoidFraction.H"
#include "locateModel.H"
#include "particleAveraging.H"
#include "undisturbedVelocity.H"
#include "volPointInterpolation.H"

using namespace Foam;
using namespace Foam::foamDEM;

namespace
{

label nPassed = 0;
label nFailed = 0;

//- The averaging's cut-off: with smoothing, cells whose smoothed solid
//  fraction is at most relCutoff x its maximum get no average (the
//  default of particleAveraging, given explicitly below)
const scalar relCutoff = 1e-10;

template<class... Args>
std::string str(const Args&... args)
{
    OStringStream os;
    os.precision(3);
    (void)std::initializer_list<int>{((void)(os << args), 0)...};
    return os.str();
}

//- Record a check; collective in parallel: passes only if it passes on
//  every processor (the message is the master's)
void check(bool ok, const std::string& what)
{
    ok = returnReduce(ok, andOp<bool>());
    if (ok)
    {
        ++nPassed;
        Info<< "PASS " << what.c_str() << nl;
    }
    else
    {
        ++nFailed;
        Info<< "FAIL " << what.c_str() << nl;
    }
}


//- Particle positions and radii
struct particleSet
{
    DynamicList<point> x;
    DynamicList<scalar> r;
    void add(const point& p, scalar radius) { x.append(p); r.append(radius); }
    void add(const particleSet& s) { x.append(s.x); r.append(s.r); }
    label size() const { return x.size(); }
};


exchangePlan testPlan()
{
    exchangePlan plan;
    for (quantity q : {quantity::position, quantity::radius,
                       quantity::velocity, quantity::id})
    {
        plan.need(q, "testVoidFraction");
    }
    return plan;
}


//- Particle data located in the mesh by the library's locate model
particleData makeParticles(const fvMesh& mesh, const particleSet& s)
{
    particleData p;
    p.resize(s.size(), testPlan());
    p.position = s.x;
    p.radius = s.r;
    p.velocity = Zero;
    p.id = identity(s.size());

    dictionary dict;
    dict.add("locate", word("hinted"));
    locateModel::New(dict, mesh)->locate(p);
    return p;
}


scalar typicalCellSize(const fvMesh& mesh)
{
    return Foam::cbrt(gAverage(mesh.V()));
}


dictionary couplingDict(const word& model, const dictionary& coeffs)
{
    dictionary dict;
    dict.add("voidFraction", model);
    dict.add(word(model + "Coeffs"), coeffs);
    return dict;
}


//- Solid fraction from the model's cell weights, before smoothing
scalarField rawSolidFraction
(
    const fvMesh& mesh,
    const particleData& p,
    const particleCellWeights& w
)
{
    scalarField s(mesh.nCells(), Zero);
    for (label i = 0; i < p.size(); ++i)
    {
        for (label k = w.start(i); k < w.end(i); ++k)
        {
            s[w.cell(k)] += w.weight(k)*p.volume(i);
        }
    }
    return s/mesh.V();
}


struct expectations
{
    bool noClipping = false;     // nothing may be clipped
    bool clipping = false;       // something must be clipped
    bool noLoss = true;          // all solid volume must be kept
    bool needsPosition = false;  // model must ask for positions
};


//- Run one model on one particle set and check everything; returns the
//  model for further checks
autoPtr<voidFractionModel> testModel
(
    const fvMesh& mesh,
    const word& name,
    const dictionary& dict,
    particleData& p,
    const expectations& expect,
    volScalarField& alpha
)
{
    Info<< nl << "== " << name.c_str() << nl;
    autoPtr<voidFractionModel> model = voidFractionModel::New(dict, mesh);

    // Exchange plan
    {
        exchangePlan plan;
        model->addRequirements(plan);
        check(plan.has(quantity::radius), name + ": asks for radius");
        if (expect.needsPosition)
        {
            check(plan.has(quantity::position), name + ": asks for position");
        }
    }

    model->compute(p, alpha);
    const scalar alphaMin = model->alphaMin();
    const scalarField& V = mesh.V();

    // Bounds, cells and patches
    {
        scalar aMin = gMin(alpha.primitiveField());
        scalar aMax = gMax(alpha.primitiveField());
        for (const fvPatchScalarField& pf : alpha.boundaryField())
        {
            if (pf.size())
            {
                aMin = min(aMin, min(pf));
                aMax = max(aMax, max(pf));
            }
        }
        check
        (
            aMin >= alphaMin && aMax <= 1,
            str(name, ": bounds ", aMin, " .. ", aMax, " in [", alphaMin,
                ", 1]")
        );
    }

    // Conservation
    scalar particleVolume = 0;
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0)
        {
            particleVolume += p.volume(i);
        }
    }
    reduce(particleVolume, sumOp<scalar>());
    const scalar solidInMesh = gSum((1 - alpha.primitiveField())*V);
    const scalar lost = model->lostSolidVolume();
    const scalar conservationError =
        mag(solidInMesh + lost - particleVolume)/particleVolume;
    check
    (
        conservationError <= 1e-12,
        str(name, ": conservation, relative error ", conservationError,
            " (nClipped ", model->nClipped(), ", clipped volume fraction ",
            model->clippedVolume()/particleVolume, ", lost fraction ",
            lost/particleVolume, ")")
    );
    if (expect.noLoss)
    {
        check
        (
            mag(lost) <= 1e-14*particleVolume,
            str(name, ": no solid volume lost (", lost/particleVolume, ")")
        );
    }
    if (expect.noClipping)
    {
        check
        (
            model->nClipped() == 0,
            str(name, ": nothing clipped (nClipped ", model->nClipped(), ")")
        );
    }
    if (expect.clipping)
    {
        check
        (
            model->nClipped() > 0 && model->clippedVolume() > 0,
            str(name, ": clipping reported (nClipped ", model->nClipped(),
                ")")
        );
    }

    // Cell weights and particle void fraction
    const particleCellWeights& w = model->cellWeights();
    {
        bool ok = w.nParticles() == p.size();
        scalar maxSumError = 0;
        scalar maxEpsError = 0;
        bool epsBounded = true;
        for (label i = 0; ok && i < p.size(); ++i)
        {
            if (p.cell[i] < 0)
            {
                ok = w.start(i) == w.end(i) && p.voidFraction[i] == 1;
                continue;
            }
            scalar sumW = 0;
            scalar eps = 0;
            for (label k = w.start(i); k < w.end(i); ++k)
            {
                const label c = w.cell(k);
                ok = ok && c >= 0 && c < mesh.nCells() && w.weight(k) > 0;
                if (!ok) break;
                sumW += w.weight(k);
                eps += w.weight(k)*alpha[c];
            }
            maxSumError = max(maxSumError, mag(sumW - 1));
            maxEpsError = max(maxEpsError, mag(eps - p.voidFraction[i]));
            epsBounded = epsBounded
                && p.voidFraction[i] >= alphaMin*(1 - 1e-14)
                && p.voidFraction[i] <= 1 + 1e-14;
        }
        check
        (
            ok && maxSumError <= 1e-14,
            str(name, ": weights valid, per particle sum 1 (max error ",
                maxSumError, "), none outside the mesh; ", w.size(),
                " pairs for ", p.size(), " particles")
        );
        check
        (
            maxEpsError <= 1e-14 && epsBounded,
            str(name, ": particle eps = sum_c w_ic eps_c (max error ",
                maxEpsError, "), bounded")
        );
    }

    // Smoothing: no new maxima, no negative values
    const scalarField s0(rawSolidFraction(mesh, p, w));
    if (model->smooths())
    {
        const scalarField& s = model->solidFraction();
        const scalar s0Max = gMax(s0);
        check
        (
            gMax(s) <= s0Max*(1 + 1e-12) && gMin(s) >= -1e-12*s0Max
         && gMax(s) < s0Max,
            str(name, ": smoothing: max ", gMax(s), " < unsmoothed max ",
                s0Max, ", min ", gMin(s))
        );
    }

    // Averaging a uniform velocity
    particleAveraging averaging(mesh, relCutoff);
    {
        exchangePlan plan;
        averaging.addRequirements(plan);
        check
        (
            plan.has(quantity::velocity) && plan.has(quantity::radius),
            "particleAveraging: asks for velocity and radius"
        );
    }
    volVectorField Us
    (
        IOobject
        (
            "Us." + name, mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedVector("zero", dimVelocity, Zero)
    );
    {
        const vector v0(0.3, -1.2, 0.05);
        p.velocity = v0;
        averaging.average(p, model(), Us);
        scalar maxError = 0;
        bool zeroElsewhere = true;
        label nWithParticles = 0;
        forAll(Us, c)
        {
            if (s0[c] > 0)
            {
                ++nWithParticles;
                maxError = max(maxError, mag(Us[c] - v0)/mag(v0));
            }
            else if (!model->smooths())
            {
                zeroElsewhere = zeroElsewhere && Us[c] == vector::zero;
            }
        }
        check
        (
            maxError <= 1e-12 && zeroElsewhere,
            str(name, ": uniform velocity averaged back in ", nWithParticles,
                " cells with particles, max relative error ", maxError,
                (model->smooths() ? "" : ", zero elsewhere"))
        );
    }

    // Averaging conserves momentum sum_i V_i v_i
    {
        Random rnd(4711);
        forAll(p.velocity, i)
        {
            p.velocity[i] = rnd.position(vector(-1, -1, -1), vector(1, 1, 1));
        }
        averaging.average(p, model(), Us);
        vector particleMomentum = Zero;
        forAll(p.cell, i)
        {
            if (p.cell[i] >= 0)
            {
                particleMomentum += p.volume(i)*p.velocity[i];
            }
        }
        reduce(particleMomentum, sumOp<vector>());
        const vector cellMomentum =
            gSum(Us.primitiveField()*model->solidFraction()*V);
        scalar scale = 0;
        forAll(p.cell, i)
        {
            if (p.cell[i] >= 0)
            {
                scale += p.volume(i)*mag(p.velocity[i]);
            }
        }
        reduce(scale, sumOp<scalar>());
        const scalar error = mag(cellMomentum - particleMomentum)/scale;

        // What the cut-off may drop: a cell below it holds
        // q_m s_c + S(sum_i w_ic V_i (q_i - q_m))/V_c, and the filter S is
        // a positive linear operator that gives s_c from the same weights,
        // so its magnitude is at most s_c (|q_m| + max_i |q_i - q_m|).
        // Without smoothing nothing is dropped: round-off only.
        scalar tail = 0;
        if (model->smooths())
        {
            scalar sumV = 0;
            vector qm = Zero;
            forAll(p.cell, i)
            {
                if (p.cell[i] >= 0)
                {
                    sumV += p.volume(i);
                    qm += p.volume(i)*p.velocity[i];
                }
            }
            reduce(sumV, sumOp<scalar>());
            reduce(qm, sumOp<vector>());
            qm /= sumV;
            scalar maxDev = 0;
            forAll(p.cell, i)
            {
                if (p.cell[i] >= 0)
                {
                    maxDev = max(maxDev, mag(p.velocity[i] - qm));
                }
            }
            reduce(maxDev, maxOp<scalar>());
            const scalarField& sf = model->solidFraction();
            const scalar cutoff = relCutoff*gMax(sf);
            forAll(sf, c)
            {
                if (sf[c] <= cutoff)
                {
                    tail += mag(sf[c])*V[c];
                }
            }
            tail = returnReduce(tail, sumOp<scalar>())*(mag(qm) + maxDev);
        }
        const scalar bound = 1e-12 + tail/scale;
        check
        (
            error <= bound,
            str(name, ": averaging conserves sum_i V_i v_i, relative error ",
                error, " (bound ", bound, ": round-off 1e-12 and what the "
                "cut-off may drop, ", tail/scale, ")")
        );

        // A weighted average: within the particles' range, per component
        vector vMin = vector::uniform(GREAT), vMax = vector::uniform(-GREAT);
        forAll(p.cell, i)
        {
            if (p.cell[i] >= 0)
            {
                vMin = min(vMin, p.velocity[i]);
                vMax = max(vMax, p.velocity[i]);
            }
        }
        reduce(vMin, minOp<vector>());
        reduce(vMax, maxOp<vector>());
        const scalar tol = 1e-12*cmptMax(vMax - vMin);
        label nOut = 0;
        forAll(Us, c)
        {
            if (s0[c] > 0)
            {
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    nOut += Us[c][d] < vMin[d] - tol || Us[c][d] > vMax[d] + tol;
                }
            }
        }
        check
        (
            returnReduce(nOut, sumOp<label>()) == 0,
            str(name, ": averages of random velocities lie within the "
                "particles' range (", nOut, " components outside)")
        );
        p.velocity = Zero;
    }

    return model;
}


// * * * * * * * * * * * * * * * * Particle sets * * * * * * * * * * * * * //

//- Small particles everywhere, also on faces, edges, points, walls and
//  outside. Index of a particle well inside one cell and of one centred on
//  an internal face.
particleSet diluteSet(const fvMesh& mesh, label& insideOne, label& onFace)
{
    Random rnd(12345);
    const scalar h = typicalCellSize(mesh);
    const boundBox bb(mesh.points());
    particleSet s;

    // Random, in a box a bit larger than the mesh: some fall outside
    for (label i = 0; i < 60; ++i)
    {
        s.add
        (
            rnd.position(bb.min() - point::uniform(0.5*h),
                         bb.max() + point::uniform(0.5*h)),
            h*(0.05 + 0.25*rnd.sample01<scalar>())
        );
    }

    // Well inside the largest cell
    insideOne = s.size();
    s.add(mesh.C()[findMax(mesh.V())], 0.05*h);

    // On internal face centres
    onFace = s.size();
    for (label i = 0; i < 6; ++i)
    {
        const label f = rnd.position<label>(0, mesh.nInternalFaces() - 1);
        s.add(mesh.faceCentres()[f], 0.3*h);
    }

    // On mesh points (cell corners, also on the boundary) and edge centres
    for (label i = 0; i < 6; ++i)
    {
        s.add(mesh.points()[rnd.position<label>(0, mesh.nPoints() - 1)], 0.2*h);
        const edge& e = mesh.edges()[rnd.position<label>(0, mesh.nEdges() - 1)];
        s.add(e.centre(mesh.points()), 0.2*h);
    }

    // Straddling walls: centre inside, half a radius from a boundary face
    for (label i = 0; i < 6; ++i)
    {
        const label f = mesh.nInternalFaces()
          + rnd.position<label>(0, mesh.nBoundaryFaces() - 1);
        const vector n = mesh.faceAreas()[f]/mag(mesh.faceAreas()[f]);
        s.add(mesh.faceCentres()[f] - 0.15*h*n, 0.3*h);
    }

    // Outside
    s.add(bb.max() + point::uniform(h), 0.3*h);
    s.add(bb.min() - point(h, 0, 0), 0.3*h);
    s.add(bb.midpoint() + vector(0, 0, bb.span().z()), 0.3*h);

    return s;
}


//- Particles larger than the cells, inside and straddling walls
particleSet largeSet(const fvMesh& mesh)
{
    Random rnd(777);
    const scalar h = typicalCellSize(mesh);
    const boundBox bb(mesh.points());
    particleSet s;
    for (label i = 0; i < 8; ++i)
    {
        const label c = rnd.position<label>(0, mesh.nCells() - 1);
        s.add(mesh.C()[c], h*(0.8 + 0.7*rnd.sample01<scalar>()));
    }
    for (label i = 0; i < 3; ++i)
    {
        const label f = mesh.nInternalFaces()
          + rnd.position<label>(0, mesh.nBoundaryFaces() - 1);
        const vector n = mesh.faceAreas()[f]/mag(mesh.faceAreas()[f]);
        s.add(mesh.faceCentres()[f] - 0.3*h*n, 1.2*h);
    }
    return s;
}


//- A dense cluster: 2h x 2h x 2h packed with small particles
particleSet denseSet(const fvMesh& mesh)
{
    Random rnd(99);
    const scalar h = typicalCellSize(mesh);
    const point centre = mesh.C()[mesh.nCells()/2];
    particleSet s;
    for (label i = 0; i < 150; ++i)
    {
        s.add
        (
            rnd.position(centre - point::uniform(h), centre + point::uniform(h)),
            0.35*h
        );
    }
    return s;
}


volScalarField makeAlpha(const fvMesh& mesh, const word& name)
{
    return volScalarField
    (
        IOobject
        (
            name, mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar("one", dimless, 1),
        voidFractionModel::patchTypes(mesh)
    );
}


//- The model configurations every suite runs
List<Tuple2<word, dictionary>> modelConfigs(scalar h)
{
    List<Tuple2<word, dictionary>> configs;

    configs.append({"centre", couplingDict("centre", dictionary())});
    configs.append({"divided", couplingDict("divided", dictionary())});
    {
        dictionary coeffs;
        coeffs.add("base", word("centre"));
        coeffs.add("smoothingLength", 1.5*h);
        configs.append({"smoothed(centre)", couplingDict("smoothed", coeffs)});
    }
    {
        dictionary coeffs;
        coeffs.add("base", word("divided"));
        coeffs.add("smoothingLengthInDiameters", 2.0);
        configs.append
        (
            {"smoothed(divided)", couplingDict("smoothed", coeffs)}
        );
    }
    return configs;
}


bool usesDivided(const word& label)
{
    return label.find("divided") != std::string::npos;
}


// * * * * * * * * * * * * * * * * * Suites  * * * * * * * * * * * * * * * //

//- One hinted locate over coupling steps as the library drives it: the
//  step's first call on the DEM's list (whose hints are kept by list
//  position), later calls on other particles (as the parallel transfer
//  locates queries and arrivals, hinted by DEM id); between steps the
//  particles move by up to a cell and the list is reordered, as a DEM
//  sort or exchange reorders it. Every cell must be findCell's (the hints
//  only choose where the search starts).
void hintSteps(const fvMesh& mesh)
{
    const scalar h = typicalCellSize(mesh);
    Random rnd(7654321);
    const boundBox bb(mesh.bounds());
    const label n = 3000;

    // Positions well inside the box, by DEM id
    List<point> x(n);
    forAll(x, i)
    {
        x[i] = bb.min() + 0.1*bb.span()
          + cmptMultiply(0.8*rnd.sample01<vector>(), bb.span());
    }

    dictionary dict;
    dict.add("locate", word("hinted"));
    autoPtr<locateModel> loc(locateModel::New(dict, mesh));

    labelList order(identity(n));
    label nWrong = 0, nChecked = 0;
    auto checkCells = [&](const particleData& p)
    {
        forAll(p.cell, i)
        {
            const label c = mesh.findCell(p.position[i], polyMesh::CELL_TETS);
            if (c >= 0 && p.cell[i] != c) ++nWrong;
            ++nChecked;
        }
    };

    for (label step = 0; step < 4; ++step)
    {
        loc->beginStep();

        // The DEM's list: ids in 'order', minus the last tenth (on another
        // rank this step)
        const label nMain = n - n/10;
        particleData p;
        p.resize(nMain, testPlan());
        forAll(p.position, k)
        {
            p.id[k] = order[k];
            p.position[k] = x[order[k]];
            p.radius[k] = 0.1*h;
        }
        p.velocity = Zero;
        loc->locate(p);
        checkCells(p);

        // The rest, located in a later call by id (queries, arrivals)
        particleData q;
        q.resize(n - nMain, testPlan());
        forAll(q.position, k)
        {
            q.id[k] = order[nMain + k];
            q.position[k] = x[order[nMain + k]];
            q.radius[k] = 0.1*h;
        }
        q.velocity = Zero;
        loc->locate(q);
        checkCells(q);

        // Next step: move by up to a cell, reorder (step 2 keeps the order)
        forAll(x, i)
        {
            x[i] += h*(2*rnd.sample01<vector>() - vector::one);
            x[i] = max(min(x[i], bb.max() - 0.01*bb.span()),
                       bb.min() + 0.01*bb.span());
        }
        if (step != 1)
        {
            for (label i = n - 1; i > 0; --i)
            {
                std::swap(order[i], order[rnd.position<label>(0, i)]);
            }
        }
    }
    Info<< "hinted locate over 4 steps (moved, reordered, split calls): "
        << nWrong << " of " << nChecked << " cells differ from findCell" << nl;
    check
    (
        nWrong == 0 && nChecked == 4*n,
        str("locate hints: every cell findCell's over reordered steps (",
            nWrong, " of ", nChecked, " differ)")
    );
}


void boxSuite(const fvMesh& mesh)
{
    hintSteps(mesh);

    const scalar h = typicalCellSize(mesh);
    volScalarField alpha(makeAlpha(mesh, "alpha"));

    label insideOne = -1, onFace = -1;
    const particleSet dilute(diluteSet(mesh, insideOne, onFace));
    particleData p(makeParticles(mesh, dilute));
    label nOutside = 0;
    forAll(p.cell, i)
    {
        nOutside += p.cell[i] < 0;
    }
    Info<< "dilute set: " << p.size() << " particles, " << nOutside
        << " outside the mesh; typical cell size " << h << " m" << nl;
    check(nOutside > 0, "dilute set has particles outside the mesh");

    for (const auto& config : modelConfigs(h))
    {
        expectations expect;
        expect.noClipping = true;
        expect.needsPosition = usesDivided(config.first());
        autoPtr<voidFractionModel> model = testModel
        (
            mesh, "dilute " + config.first(), config.second(), p, expect,
            alpha
        );

        const particleCellWeights& w = model->cellWeights();
        if (config.first() == "centre")
        {
            bool same = true;
            forAll(p.cell, i)
            {
                same = same
                 && (p.cell[i] < 0
                  || (w.end(i) == w.start(i) + 1
                   && w.cell(w.start(i)) == p.cell[i]
                   && w.weight(w.start(i)) == 1
                   && p.voidFraction[i] == alpha[p.cell[i]]));
            }
            check(same, "centre: weight 1 in the particle's cell, sees its eps");
        }
        if (config.first() == "divided")
        {
            check
            (
                w.end(insideOne) - w.start(insideOne) == 1,
                "divided: a particle well inside a cell stays in it"
            );
            label nSplit = 0;
            for (label i = onFace; i < onFace + 6; ++i)
            {
                nSplit += (w.end(i) - w.start(i) >= 2);
            }
            check
            (
                nSplit == 6,
                str("divided: particles on internal faces split over >= 2 "
                    "cells (", nSplit, " of 6)")
            );
        }
    }

    // divided's sub-volume points: 33, centroid at the centre, second
    // moment of the shells: 3/5 (1 - rCore^5) R^2 with rCore^3 = 1/33
    {
        autoPtr<voidFractionModel> model =
            voidFractionModel::New(couplingDict("divided", dictionary()), mesh);
        const List<vector>& u =
            refCast<const dividedVoidFraction>(model()).unitPoints();
        const vectorField pts(u);
        const scalar secondMoment = sum(magSqr(pts))/pts.size();
        const scalar expected = 0.6*(1 - Foam::pow(1.0/33, 5.0/3));
        check
        (
            pts.size() == 33 && mag(sum(pts)) < 1e-14
         && mag(secondMoment - expected) < 1e-14 && max(mag(pts)) < 1,
            str("divided: 33 points, centroid ", mag(sum(pts)),
                ", second moment ", secondMoment, " (expected ", expected,
                ")")
        );
    }

    // Larger than cells: clipped, the excess redistributed
    particleData pLarge(makeParticles(mesh, largeSet(mesh)));
    for (const auto& config : modelConfigs(h))
    {
        expectations expect;
        expect.needsPosition = usesDivided(config.first());
        if (config.first() == "centre" || config.first() == "divided")
        {
            expect.clipping = true;
        }
        testModel
        (
            mesh, "large " + config.first(), config.second(), pLarge, expect,
            alpha
        );
    }

    // Dense cluster
    particleData pDense(makeParticles(mesh, denseSet(mesh)));
    for (const auto& config : modelConfigs(h))
    {
        expectations expect;
        expect.needsPosition = usesDivided(config.first());
        expect.clipping = true;
        testModel
        (
            mesh, "dense " + config.first(), config.second(), pDense, expect,
            alpha
        );
    }

    // Without redistribution the excess is lost, and reported
    {
        dictionary coeffs;
        coeffs.add("redistributeClipped", false);
        coeffs.add("alphaMin", 0.5);
        expectations expect;
        expect.clipping = true;
        expect.noLoss = false;
        autoPtr<voidFractionModel> model = testModel
        (
            mesh, "dense centre, no redistribution, alphaMin 0.5",
            couplingDict("centre", coeffs), pDense, expect, alpha
        );
        check
        (
            mag(model->lostSolidVolume() - model->clippedVolume())
         <= 1e-12*model->clippedVolume()
         && model->lostSolidVolume() > 0,
            str("no redistribution: lost volume ", model->lostSolidVolume(),
                " = clipped excess ", model->clippedVolume())
        );
        check
        (
            gMin(alpha.primitiveField()) == 0.5,
            str("alphaMin 0.5 reached: min eps ", gMin(alpha.primitiveField()))
        );
    }

    // The layers' limit: with none the whole excess is lost; with one, the
    // first layer around each clipped group is filled to the bound and the
    // rest is lost, and reported (testModel checks the volume account)
    for (const label nLayers : {0, 1})
    {
        dictionary coeffs;
        coeffs.add("alphaMin", 0.5);
        coeffs.add("maxRedistributionSweeps", nLayers);
        expectations expect;
        expect.clipping = true;
        expect.noLoss = false;
        autoPtr<voidFractionModel> model = testModel
        (
            mesh, str("dense centre, alphaMin 0.5, ", nLayers, " layer(s)"),
            couplingDict("centre", coeffs), pDense, expect, alpha
        );
        const scalar lost = model->lostSolidVolume();
        const scalar clipped = model->clippedVolume();
        check
        (
            nLayers == 0
          ? mag(lost - clipped) <= 1e-12*clipped
          : lost > 0 && lost < clipped,
            str(nLayers, " layer(s): lost ", lost, " of the clipped excess ",
                clipped)
        );
    }
}


//- divided's sub-volume points in a concave domain (lshape: an L-shaped
//  duct of convex hexahedra), located by its face walks (a point that
//  leaves through a wall: its test against the mesh's reach past that
//  wall, else an octree search) against OpenFOAM's findCell (CELL_TETS)
//  at each point; points outside the mesh count in the particle's cell,
//  as the model defines. Particles of radius 1.5 cells within 2 mm of the
//  re-entrant edge (x = z = 5 mm), so that points leave through a wall
//  next to the edge and lie in the other arm.
void concaveSuite(const fvMesh& mesh)
{
    autoPtr<voidFractionModel> model =
        voidFractionModel::New(couplingDict("divided", dictionary()), mesh);
    const List<vector>& u =
        refCast<const dividedVoidFraction>(model()).unitPoints();

    const scalar h = typicalCellSize(mesh);
    Random rnd(24681357);
    particleSet s;
    while (s.size() < 2000)
    {
        const point x
        (
            0.003 + 0.004*rnd.sample01<scalar>(),
            0.004*rnd.sample01<scalar>(),
            0.003 + 0.004*rnd.sample01<scalar>()
        );
        if (mesh.findCell(x, polyMesh::CELL_TETS) < 0) continue;
        s.add(x, 1.5*h);
    }
    const particleData p(makeParticles(mesh, s));
    particleCellWeights w;
    model->distribute(p, w);

    label nDiffer = 0, nPast = 0;
    forAll(p.cell, i)
    {
        // The reference: each point's cell by findCell, own if outside
        Map<scalar> ref;
        bool past = false;
        forAll(u, j)
        {
            const point y = p.position[i] + p.radius[i]*u[j];
            label c = j == 0 ? p.cell[i] : mesh.findCell(y, polyMesh::CELL_TETS);
            if (c < 0)
            {
                c = p.cell[i];
                past = true;
            }
            ref(c) += 1.0/u.size();
        }
        nPast += past;
        Map<scalar> got;
        for (label k = w.start(i); k < w.end(i); ++k)
        {
            got(w.cell(k)) += w.weight(k);
        }
        bool same = got.size() == ref.size();
        forAllConstIters(ref, iter)
        {
            same = same && mag(got.lookup(iter.key(), -1) - iter.val()) < 1e-12;
        }
        nDiffer += !same;
    }
    Info<< "divided: " << p.size() << " particles, " << nPast
        << " reaching outside the mesh; sub-volume cells differ from"
        << " findCell's for " << nDiffer << nl;
    check(nPast > p.size()/10, str("divided: ", nPast, " particles reach past a wall"));
    check
    (
        nDiffer == 0,
        str("divided: sub-volume cells as findCell's for every particle (",
            nDiffer, " of ", p.size(), " differ)")
    );
}


//- Locate on a snapped mesh (hexahedra cut at the walls, prisms and
//  polyhedra, some not convex): hinted locate, whose face-plane tests are
//  exact only for convex cells, against OpenFOAM's findCell with the cells
//  cut into tetrahedra from their centres (CELL_TETS: exact for any cell
//  star-shaped about its centre; the default FACE_DIAG_TRIS mode missed
//  1.7 % of the points here, points that CELL_TETS puts in the cell hinted
//  found), at random points in random cells' bounding boxes; then the box
//  suite's checks on this mesh
void snappedSuite(const fvMesh& mesh)
{
    // Random points in the bounding boxes of random cells (10 % larger):
    // inside those cells, their neighbours, or outside the mesh near walls
    Random rnd(1234567);
    const label n = 20000;
    particleSet s;
    for (label i = 0; i < n; ++i)
    {
        const label c = rnd.position<label>(0, mesh.nCells() - 1);
        boundBox cb(mesh.points(), mesh.cellPoints()[c], false);
        cb.inflate(0.1);
        s.add(cb.min() + cmptMultiply(rnd.sample01<vector>(), cb.span()), 0);
    }
    const particleData p(makeParticles(mesh, s));
    label nIn = 0, nWrong = 0, nMissed = 0, nExtra = 0;
    label nNonHex = 0;
    scalar worstExtra = 0;
    forAll(p.cell, i)
    {
        const label c = mesh.findCell(p.position[i], polyMesh::CELL_TETS);
        if (c >= 0)
        {
            ++nIn;
            nNonHex += mesh.cells()[c].size() != 6;
            if (p.cell[i] < 0) ++nMissed;
            else if (p.cell[i] != c) ++nWrong;
        }
        else if (p.cell[i] >= 0)
        {
            ++nExtra;
            // how far outside: distance to the nearest boundary face centre
            // relative to the cell's size
            scalar dMin = GREAT;
            for (const label f : mesh.cells()[p.cell[i]])
            {
                if (!mesh.isInternalFace(f))
                {
                    dMin = min(dMin, mag(mesh.faceCentres()[f] - p.position[i]));
                }
            }
            worstExtra = max(worstExtra, dMin/Foam::cbrt(mesh.V()[p.cell[i]]));
        }
    }
    Info<< "locate: " << nIn << " of " << n << " random points in the mesh ("
        << nNonHex << " in cells that are not six-faced), " << nWrong
        << " in another cell, " << nMissed << " not found, " << nExtra
        << " found outside (farthest from a boundary face centre of its cell: "
        << worstExtra << " cell sizes)" << nl;
    check(nIn > n/10, str("locate: ", nIn, " random points in the mesh"));
    check
    (
        nWrong == 0 && nMissed == 0 && nExtra == 0,
        str("locate: hinted agrees with findCell (tetrahedra) at all ", n,
            " points (", nWrong, " in another cell, ", nMissed,
            " not found, ", nExtra, " found outside)")
    );

    boxSuite(mesh);
}


void periodicSuite(const fvMesh& mesh)
{
    const scalar h = typicalCellSize(mesh);
    const boundBox bb(mesh.points());
    const scalar Lx = bb.span().x();
    volScalarField alpha(makeAlpha(mesh, "alpha"));

    // Straddling the periodic planes, plus random ones
    particleSet s;
    const label atLeft = 0;
    s.add(bb.min() + vector(0.2*h, 3.1*h, 3*h), 0.8*h);
    const label atRight = 1;
    s.add(bb.min() + vector(Lx - 0.3*h, 2*h, 2.5*h), 0.6*h);
    Random rnd(2024);
    for (label i = 0; i < 30; ++i)
    {
        s.add(rnd.position(bb.min(), bb.max()), h*(0.1 + 0.4*rnd.sample01<scalar>()));
    }
    particleData p(makeParticles(mesh, s));

    for (const auto& config : modelConfigs(h))
    {
        expectations expect;
        expect.needsPosition = usesDivided(config.first());
        autoPtr<voidFractionModel> model = testModel
        (
            mesh, "periodic " + config.first(), config.second(), p, expect,
            alpha
        );
        if (usesDivided(config.first()))
        {
            // Sub-volumes beyond a periodic plane land on the other side
            const particleCellWeights& w = model->cellWeights();
            scalar wrappedLeft = 0, wrappedRight = 0;
            for (label k = w.start(atLeft); k < w.end(atLeft); ++k)
            {
                if (mesh.C()[w.cell(k)].x() > bb.midpoint().x())
                {
                    wrappedLeft += w.weight(k);
                }
            }
            for (label k = w.start(atRight); k < w.end(atRight); ++k)
            {
                if (mesh.C()[w.cell(k)].x() < bb.midpoint().x())
                {
                    wrappedRight += w.weight(k);
                }
            }
            check
            (
                wrappedLeft > 0 && wrappedRight > 0,
                str(config.first(), ": weight across the periodic plane ",
                    wrappedLeft, " (particle at x = 0.2h), ", wrappedRight,
                    " (at x = L - 0.3h)")
            );
        }
    }

    // Smoothing across the periodic plane: one particle in the middle of a
    // first-layer cell; the cells one cell away on either side (across the
    // plane and inside) must get the same smoothed solid fraction
    {
        particleSet one;
        const point x0 = bb.min() + vector(0.5*h, 2.5*h, 2.5*h);
        one.add(x0, 0.4*h);
        particleData p1(makeParticles(mesh, one));

        dictionary coeffs;
        coeffs.add("base", word("centre"));
        coeffs.add("smoothingLength", 1.5*h);
        autoPtr<voidFractionModel> model =
            voidFractionModel::New(couplingDict("smoothed", coeffs), mesh);
        model->compute(p1, alpha);
        const scalarField& sf = model->solidFraction();

        const label inside = mesh.findCell(x0 + vector(h, 0, 0));
        const label across = mesh.findCell(x0 + vector(Lx - h, 0, 0));
        const label far = mesh.findCell(x0 + vector(0.5*Lx, 0, 0));
        if (inside < 0 || across < 0 || far < 0)
        {
            check(false, "periodic suite: cells for the symmetry check found");
            return;
        }
        const scalar asymmetry =
            mag(sf[across] - sf[inside])/sf[inside];
        check
        (
            asymmetry <= 1e-9 && sf[across] > 10*sf[far],
            str("smoothed: same solid fraction one cell away inside (",
                sf[inside], ") and across the periodic plane (", sf[across],
                "), relative difference ", asymmetry, "; far ", sf[far])
        );
    }
}


//- Run on a decomposed mesh: random particles, small and large, every
//  model; checks as in the other suites, over all processors
void parallelSuite(const fvMesh& mesh)
{
    label nProcPatches = 0;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        nProcPatches += isA<processorPolyPatch>(pp) ? 1 : 0;
    }
    check
    (
        Pstream::parRun() && returnReduce(nProcPatches, sumOp<label>()) > 0,
        str("running on ", Pstream::nProcs(), " processors with processor"
            " patches")
    );

    const boundBox bb(mesh.points(), true);
    const scalar h = typicalCellSize(mesh);
    Random rnd(31);
    particleSet s;
    for (label i = 0; i < 80; ++i)
    {
        s.add(rnd.position(bb.min(), bb.max()), h*(0.1 + 0.3*rnd.sample01<scalar>()));
    }
    for (label i = 0; i < 6; ++i)
    {
        s.add(rnd.position(bb.min(), bb.max()), h*(0.8 + 0.5*rnd.sample01<scalar>()));
    }
    particleData p(makeParticles(mesh, s));
    const label nLocated = returnReduce
    (
        label(std::count_if(p.cell.begin(), p.cell.end(),
                            [](label c){ return c >= 0; })),
        sumOp<label>()
    );
    Info<< nLocated << " of " << s.size() << " particles located" << nl;

    volScalarField alpha(makeAlpha(mesh, "alpha"));
    for (const auto& config : modelConfigs(h))
    {
        expectations expect;
        expect.needsPosition = usesDivided(config.first());
        testModel
        (
            mesh, "parallel " + config.first(), config.second(), p, expect,
            alpha
        );
    }
}


//- Not a test: wall time of compute() and average() per model for many
//  particles (-nParticles, default 50000; radius -radius cells, 0.3)
void timingSuite(const fvMesh& mesh, label nParticles, scalar radiusInCells)
{
    const boundBox bb(mesh.points(), true);
    const scalar h = typicalCellSize(mesh);
    Random rnd(5);
    particleSet s;
    for (label i = 0; i < nParticles; ++i)
    {
        s.add(rnd.position(bb.min(), bb.max()), radiusInCells*h);
    }
    particleData p(makeParticles(mesh, s));
    p.velocity = vector(1, 0, 0);
    volScalarField alpha(makeAlpha(mesh, "alpha"));
    volVectorField Us
    (
        IOobject("Us", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector("zero", dimVelocity, Zero)
    );
    particleAveraging averaging(mesh);
    for (const auto& config : modelConfigs(h))
    {
        autoPtr<voidFractionModel> model =
            voidFractionModel::New(config.second(), mesh);
        model->compute(p, alpha);   // first call builds search trees
        clockTime timer;
        model->compute(p, alpha);
        const scalar tCompute = timer.timeIncrement();
        averaging.average(p, model(), Us);
        const scalar tAverage = timer.timeIncrement();
        Info<< "timing " << config.first().c_str() << ": compute "
            << tCompute << " s, average " << tAverage << " s for "
            << nParticles << " particles, " << mesh.nCells() << " cells, "
            << model->cellWeights().size() << " weight pairs" << nl;
    }
}


void badInputSuite(const fvMesh& mesh)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    auto expectFailure = [&mesh]
    (
        const word& what,
        const dictionary& dict,
        const std::string& messagePart
    )
    {
        bool failed = false;
        std::string message;
        try
        {
            voidFractionModel::New(dict, mesh);
        }
        catch (const Foam::error& e)
        {
            failed = true;
            message = e.message();
        }
        check
        (
            failed && message.find(messagePart) != std::string::npos,
            str("bad input '", what.c_str(), "' fails with a message naming \"",
                messagePart.c_str(), "\": ", message.c_str())
        );
    };

    {
        dictionary coeffs;
        expectFailure
        (
            "smoothed without a length", couplingDict("smoothed", coeffs),
            "exactly one"
        );
    }
    {
        dictionary coeffs;
        coeffs.add("smoothingLength", 0.001);
        coeffs.add("smoothingLengthInDiameters", 2.0);
        expectFailure
        (
            "smoothed with both lengths", couplingDict("smoothed", coeffs),
            "exactly one"
        );
    }
    {
        dictionary coeffs;
        coeffs.add("smoothingLength", -0.001);
        expectFailure
        (
            "negative smoothingLength", couplingDict("smoothed", coeffs),
            "positive"
        );
    }
    {
        dictionary coeffs;
        coeffs.add("smoothingLength", 0.001);
        coeffs.add("base", word("smoothed"));
        expectFailure
        (
            "smoothed on smoothed", couplingDict("smoothed", coeffs),
            "centre or divided"
        );
    }
    {
        dictionary coeffs;
        coeffs.add("alphaMin", 1.2);
        expectFailure
        (
            "alphaMin 1.2", couplingDict("divided", coeffs), "alphaMin"
        );
    }
    expectFailure
    (
        "unknown model", couplingDict("nonsense", dictionary()), "nonsense"
    );

    // A solver sub-dictionary overrides the defaults
    {
        dictionary coeffs;
        coeffs.add("smoothingLength", 0.001);
        dictionary solver;
        solver.add("solver", word("nonsenseSolver"));
        coeffs.add("solver", solver);
        particleSet one;
        one.add(mesh.C()[0], 0.3*typicalCellSize(mesh));
        particleData p(makeParticles(mesh, one));
        volScalarField alpha(makeAlpha(mesh, "alpha"));
        bool failed = false;
        try
        {
            voidFractionModel::New(couplingDict("smoothed", coeffs), mesh)
                ->compute(p, alpha);
        }
        catch (const Foam::error& e)
        {
            failed = std::string(e.message()).find("nonsenseSolver")
                != std::string::npos;
        }
        check(failed, "smoothed: the 'solver' sub-dictionary is used");
    }

    FatalError.throwExceptions(false);
    FatalIOError.throwExceptions(false);
}

} // End anonymous namespace



//- Shaped particles (dividedCoeffs.shapes): a plate 4h x 0.8h x 0.24h at a
//  cell centre, its length along x, then turned 90 deg about z (length
//  along y). Worked by hand: shapeSubVolumes 40 gives 15 x 3 x 1 points
//  (edge / (V/40)^(1/3) rounded), at x offsets (i + 1/2) 4h/15 - 2h; per
//  column of cells along the length 2, 4, 3, 4, 2 of the 15, so the cells
//  get 2/15, 4/15, 3/15, 4/15, 2/15; the width's 3 points stay in the
//  centre cell. As a sphere of its volume-equivalent diameter (1.14 h) the
//  same particle reaches no cell two cells away.
void shapesSuite(const fvMesh& mesh)
{
    const scalar h = typicalCellSize(mesh);
    const boundBox bb(mesh.points());
    const label c0 = mesh.findCell(bb.midpoint());
    const point x0 = mesh.C()[c0];

    exchangePlan plan(testPlan());
    plan.need(quantity::type, "testVoidFraction");
    plan.need(quantity::orientation, "testVoidFraction");
    const scalar V = 4*0.8*0.24*h*h*h;
    const scalar r = 0.5*Foam::cbrt(6*V/constant::mathematical::pi);

    particleData p;
    p.resize(2, plan);
    p.position = x0;
    p.radius = r;
    p.velocity = Zero;
    p.id = identity(2);
    p.type = 1;
    p.orientation[0] = tensor::I;
    // body x along lab y: x_lab = R & x_body
    p.orientation[1] = tensor(0, -1, 0, 1, 0, 0, 0, 0, 1);
    {
        dictionary dict;
        dict.add("locate", word("hinted"));
        locateModel::New(dict, mesh)->locate(p);
    }

    dictionary plate;
    plate.add("shape", word("plate"));
    plate.add("length", 4*h);
    plate.add("width", 0.8*h);
    plate.add("thickness", 0.24*h);
    dictionary shapes;
    shapes.add("1", plate);
    dictionary coeffs;
    coeffs.add("shapes", shapes);
    autoPtr<voidFractionModel> model =
        voidFractionModel::New(couplingDict("divided", coeffs), mesh);

    {
        exchangePlan need;
        model->addRequirements(need);
        check
        (
            need.has(quantity::type) && need.has(quantity::orientation),
            "divided with shapes asks for type and orientation"
        );
    }
    volScalarField alpha(makeAlpha(mesh, "alpha"));
    model->compute(p, alpha);
    const particleCellWeights& w = model->cellWeights();

    const scalar expected[5] = {2, 4, 3, 4, 2};
    for (label i = 0; i < 2; ++i)
    {
        const vector axis(i == 0 ? vector(1, 0, 0) : vector(0, 1, 0));
        scalar total = 0, worst = 0;
        label nCells = 0;
        for (label k = w.start(i); k < w.end(i); ++k)
        {
            total += w.weight(k);
            ++nCells;
            const vector d(mesh.C()[w.cell(k)] - x0);
            const label column = label(std::lround((d & axis)/h)) + 2;
            const bool onAxis = mag(d - (d & axis)*axis) < 1e-6*h;
            const scalar want =
                (onAxis && column >= 0 && column < 5) ? expected[column]/15 : 0;
            worst = max(worst, mag(w.weight(k) - want));
        }
        check
        (
            nCells == 5 && mag(total - 1) < 1e-12 && worst < 1e-12,
            str("plate ", i == 0 ? "along x" : "turned along y", ": ", nCells,
                " cells (expected 5), weights off the hand-worked 2,4,3,4,2"
                " /15 by ", worst, ", sum ", total)
        );
    }

    // The same particle as a sphere of its volume-equivalent diameter
    autoPtr<voidFractionModel> sphere =
        voidFractionModel::New(couplingDict("divided", dictionary()), mesh);
    sphere->compute(p, alpha);
    const particleCellWeights& ws = sphere->cellWeights();
    scalar reach = 0;
    for (label k = ws.start(0); k < ws.end(0); ++k)
    {
        reach = max(reach, mag(mesh.C()[ws.cell(k)] - x0));
    }
    check
    (
        reach < 1.5*h,
        str("as a sphere (d_v = ", 2*r/h, " h) it reaches cells ", reach/h,
            " h away (< 1.5 h); as a plate 2 h")
    );
}


//- couplingKernel cellPoint (undisturbedVelocity): u_f and eps at each
//  particle are interpolated at its position. On a uniform mesh the cell-
//  point interpolation reproduces a linear field exactly (point values are
//  averages of symmetric neighbours); the cell kernel reads the cell's
//  value, off by up to |grad U| h/2. With implicit coupling the fluid's
//  implicit term sees the cell's U, and addCorrectionSource must add the
//  rest of the reaction.
void interpolationSuite(const fvMesh& mesh)
{
    const scalar h = typicalCellSize(mesh);
    const boundBox bb(mesh.points());
    const point x0 = bb.midpoint();
    const tensor G(150, -70, 30, 20, 210, -110, 90, 40, -60);   // 1/s
    const vector U0(0.3, -0.2, 0.5);
    const vector a(10, -15, 20);                                // 1/m
    auto uLin = [&](const point& x) { return U0 + (G & (x - x0)); };
    auto epsLin = [&](const point& x) { return 0.6 + (a & (x - x0)); };

    // Linear fields, boundary values the field's at the face centres
    volVectorField U
    (
        IOobject
        (
            "U", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        fixedValueFvPatchField<vector>::typeName
    );
    volScalarField alpha
    (
        IOobject
        (
            "voidFraction", mesh.time().timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        fixedValueFvPatchField<scalar>::typeName
    );
    forAll(U, c)
    {
        U[c] = uLin(mesh.C()[c]);
        alpha[c] = epsLin(mesh.C()[c]);
    }
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].coupled())
        {
            continue;
        }
        const vectorField& cf = mesh.C().boundaryField()[patchi];
        forAll(cf, f)
        {
            U.boundaryFieldRef()[patchi][f] = uLin(cf[f]);
            alpha.boundaryFieldRef()[patchi][f] = epsLin(cf[f]);
        }
    }
    U.correctBoundaryConditions();
    alpha.correctBoundaryConditions();

    // Random particles inside the box, at cell centres and at mesh points,
    // and one outside
    Random rnd(4242);
    particleSet s;
    for (label i = 0; i < 300; ++i)
    {
        s.add(rnd.position(bb.min(), bb.max()), 0.2*h);
    }
    for (label i = 0; i < 10; ++i)
    {
        s.add(mesh.C()[rnd.position<label>(0, mesh.nCells() - 1)], 0.2*h);
        s.add(mesh.points()[rnd.position<label>(0, mesh.nPoints() - 1)], 0.2*h);
    }
    s.add(bb.max() + point::uniform(h), 0.2*h);
    particleData p(makeParticles(mesh, s));
    forAll(p.velocity, i)
    {
        p.velocity[i] = vector(0.1, 0.2, -0.1)*rnd.sample01<scalar>();
    }
    label nIn = 0;
    forAll(p.cell, i)
    {
        nIn += p.cell[i] >= 0;
    }
    Info<< "interpolation: " << p.size() << " particles, " << nIn
        << " in this rank's mesh" << nl;

    autoPtr<voidFractionModel> vf =
        voidFractionModel::New(couplingDict("centre", dictionary()), mesh);

    auto kernelDict = [](const word& kernel)
    {
        dictionary dict;
        dict.add("couplingKernel", kernel);
        return dict;
    };

    // cellPoint: exact for the linear fields
    {
        undisturbedVelocity ud
        (
            kernelDict("cellPoint"), mesh, vf(), 1.2, 1.5e-5, false
        );
        p.voidFraction = -1;
        ud.read(U, alpha, p);

        // Points on the box's edges and corners: their boundary faces are
        // not coplanar
        boolList onEdge(mesh.nPoints(), false);
        forAll(mesh.pointFaces(), pt)
        {
            vector n0(Zero);
            for (const label f : mesh.pointFaces()[pt])
            {
                if (mesh.isInternalFace(f)) continue;
                const label patchi = mesh.boundaryMesh().whichPatch(f);
                if (mesh.boundaryMesh()[patchi].coupled()) continue;
                const vector n = mesh.faceAreas()[f]/mag(mesh.faceAreas()[f]);
                if (mag(n0) == 0)
                {
                    n0 = n;
                }
                else if (mag(n & n0) < 0.99)
                {
                    onEdge[pt] = true;
                }
            }
        }
        const pointScalarField alphaPoints
        (
            volPointInterpolation::New(mesh).interpolate(alpha)
        );
        scalar errU = 0, errEps = 0;
        label nExact = 0, nEdge = 0;
        bool bounded = true;
        bool outsideZero = true;
        forAll(p.cell, i)
        {
            if (p.cell[i] < 0)
            {
                outsideZero = outsideZero && mag(p.fluidVelocity[i]) == 0;
                continue;
            }
            const label c = p.cell[i];
            bool edgeCell = false;
            for (const label pt : mesh.cellPoints()[c])
            {
                edgeCell = edgeCell || onEdge[pt];
            }
            if (edgeCell)
            {
                // Bounded by the values it interpolates
                scalar lo = alpha[c], hi = alpha[c];
                for (const label pt : mesh.cellPoints()[c])
                {
                    lo = min(lo, alphaPoints[pt]);
                    hi = max(hi, alphaPoints[pt]);
                }
                bounded = bounded
                 && p.voidFraction[i] >= lo - 1e-14
                 && p.voidFraction[i] <= hi + 1e-14;
                ++nEdge;
                continue;
            }
            ++nExact;
            errU = max(errU, mag(p.fluidVelocity[i] - uLin(p.position[i])));
            errEps = max(errEps, mag(p.voidFraction[i] - epsLin(p.position[i])));
        }
        errU = returnReduce(errU, maxOp<scalar>());
        errEps = returnReduce(errEps, maxOp<scalar>());
        reduce(nExact, sumOp<label>());
        reduce(nEdge, sumOp<label>());
        check
        (
            errU < 1e-12 && errEps < 1e-12 && nExact > 100,
            str("cellPoint: a linear U and eps at the positions of ", nExact,
                " particles (cells off the box's edges) to 1e-12 (", errU,
                " m/s, ", errEps, ")")
        );
        check
        (
            bounded && nEdge > 0,
            str("cellPoint: eps at ", nEdge, " particles in cells on the"
                " box's edges within the values interpolated (the point"
                " values there average faces of two walls: not exact)")
        );
        check(outsideZero, "cellPoint: u_f = 0 for a particle outside");

        // The reaction: implicit -K (U_c - v) plus the explicit share
        // is -K (u_f - v) per particle, summed over all of them
        vectorField forceOnFluid(mesh.nCells(), Zero);
        vector implicitPart(Zero), onParticles(Zero);
        forAll(p.cell, i)
        {
            p.dragCoeff[i] = 1e-4*(1 + rnd.sample01<scalar>());
            const label c = p.cell[i];
            if (c >= 0)
            {
                implicitPart -= p.dragCoeff[i]*(U[c] - p.velocity[i]);
                onParticles +=
                    p.dragCoeff[i]*(p.fluidVelocity[i] - p.velocity[i]);
            }
        }
        ud.addCorrectionSource(p, forceOnFluid);
        const vector onFluid = returnReduce
        (
            implicitPart + sum(forceOnFluid), sumOp<vector>()
        );
        reduce(onParticles, sumOp<vector>());
        const scalar mismatch =
            mag(onFluid + onParticles)/max(mag(onParticles), VSMALL);
        check
        (
            mismatch < 1e-12,
            str("cellPoint: the fluid's implicit term and explicit share"
                " balance the particles' drag (", mismatch, ")")
        );
    }

    // cell: the cell's value, off the linear field inside the cell
    {
        undisturbedVelocity ud(kernelDict("cell"), mesh, vf(), 1.2, 1.5e-5, false);
        ud.read(U, alpha, p);
        bool cellValue = true;
        scalar offLinear = 0;
        forAll(p.cell, i)
        {
            const label c = p.cell[i];
            if (c >= 0)
            {
                cellValue = cellValue && p.fluidVelocity[i] == U[c];
                offLinear = max
                (
                    offLinear, mag(p.fluidVelocity[i] - uLin(p.position[i]))
                );
            }
        }
        offLinear = returnReduce(offLinear, maxOp<scalar>());
        check
        (
            cellValue && offLinear > 1e-2*mag(G)*h,
            str("cell: u_f is the cell's U, up to ", offLinear,
                " m/s off the linear field (|G| h = ", mag(G)*h, ")")
        );
    }

    // cellPoint with the self-induced correction: FatalIOError
    {
        FatalIOError.throwExceptions();
        dictionary dict(kernelDict("cellPoint"));
        dict.add("undisturbedVelocity", word("selfInducedCorrection"));
        std::string message;
        try
        {
            undisturbedVelocity ud(dict, mesh, vf(), 1.2, 1.5e-5, false);
        }
        catch (const Foam::error& e)
        {
            message = e.message();
        }
        FatalIOError.dontThrowExceptions();
        check
        (
            message.find("selfInducedCorrection") != std::string::npos
         && message.find("Valid undisturbedVelocity") != std::string::npos,
            str("cellPoint with selfInducedCorrection: FatalIOError \"",
                message.substr(0, 90).c_str(), "...\"")
        );
    }
}


int main(int argc, char *argv[])
{
    argList::addNote("Tests of the void fraction models and averaging");
    argList::addOption("suite", "name", "box, snapped, periodic, parallel, badInput, shapes, interpolation, concave or timing");
    argList::addOption("nParticles", "N", "timing: number of particles");
    argList::addOption("radius", "r", "timing: radius in cell sizes");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const word suite(args.getOrDefault<word>("suite", "box"));
    Info<< "Suite " << suite << ": mesh of " << mesh.nCells() << " cells"
        << nl;

    if (suite == "box")
    {
        boxSuite(mesh);
    }
    else if (suite == "snapped")
    {
        snappedSuite(mesh);
    }
    else if (suite == "periodic")
    {
        periodicSuite(mesh);
    }
    else if (suite == "parallel")
    {
        parallelSuite(mesh);
    }
    else if (suite == "concave")
    {
        concaveSuite(mesh);
    }
    else if (suite == "timing")
    {
        timingSuite
        (
            mesh,
            args.getOrDefault<label>("nParticles", 50000),
            args.getOrDefault<scalar>("radius", 0.3)
        );
    }
    else if (suite == "badInput")
    {
        badInputSuite(mesh);
    }
    else if (suite == "shapes")
    {
        shapesSuite(mesh);
    }
    else if (suite == "interpolation")
    {
        interpolationSuite(mesh);
    }
    else
    {
        FatalErrorInFunction
            << "Unknown suite " << suite << exit(FatalError);
    }

    Info<< nl << "testVoidFraction " << suite << ": " << nPassed
        << " passed, " << nFailed << " failed" << endl;

    // Not 'return 1': argList's destructor ends the program with exit(0)
    if (nFailed)
    {
        FatalErrorInFunction
            << nFailed << " check(s) failed" << exit(FatalError);
    }

    return 0;
}
