#include "particleTransfer.H"
#include "PstreamBuffers.H"

Foam::foamDEM::particleTransfer::particleTransfer(const fvMesh& mesh)
:
    mesh_(mesh),
    procBoxes_(Pstream::nProcs()),
    nDEMLocal_(0),
    sent_(Pstream::nProcs()),
    received_(Pstream::nProcs()),
    bytesSent_(0),
    nSent_(0),
    nReceived_(0)
{
    // A slightly inflated box, so that particles on a processor face are
    // asked on both sides
    treeBoundBox box(mesh.points());
    const scalar tol = 1e-6*max(box.mag(), SMALL);
    box.min() -= vector::uniform(tol);
    box.max() += vector::uniform(tol);
    procBoxes_[Pstream::myProcNo()] = box;
    Pstream::gatherList(procBoxes_);
    Pstream::scatterList(procBoxes_);
}


Foam::label Foam::foamDEM::particleTransfer::gather
(
    particleData& p,
    locateModel& locate,
    const exchangePlan& plan
)
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    nDEMLocal_ = p.size();
    bytesSent_ = 0;

    // 1. Ask the ranks whose box holds a particle that we do not contain
    labelListList asked(nProcs);
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0) continue;
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (proci != me && procBoxes_[proci].contains(p.position[i]))
            {
                asked[proci].append(i);
            }
        }
    }

    PstreamBuffers queries(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (asked[proci].size())
        {
            UOPstream os(proci, queries);
            os << pointField(UIndirectList<point>(p.position, asked[proci]))
               << labelList(UIndirectList<label>(p.id, asked[proci]));
            bytesSent_ += asked[proci].size()*(3*sizeof(scalar) + sizeof(label));
        }
    }
    labelList queriesSizes;
    queries.finishedSends(queriesSizes);

    // Answer: which of the asked positions lie in this rank's mesh
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (!queriesSizes[proci]) continue;
        UIPstream is(proci, queries);
        particleData q;
        is >> q.position >> q.id;
        q.cell.setSize(q.position.size(), -1);
        locate.locate(q);

        boolList found(q.size());
        forAll(found, k)
        {
            found[k] = q.cell[k] >= 0;
        }
        UOPstream os(proci, answers);
        os << found;
        bytesSent_ += found.size();
    }
    labelList answersSizes;
    answers.finishedSends(answersSizes);

    // 2. Each particle goes to the lowest rank that contains it
    labelList owner(p.size(), -1);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (!answersSizes[proci]) continue;
        UIPstream is(proci, answers);
        boolList found;
        is >> found;
        forAll(found, k)
        {
            const label i = asked[proci][k];
            if (found[k] && (owner[i] < 0 || proci < owner[i]))
            {
                owner[i] = proci;
            }
        }
    }

    for (labelList& s : sent_) s.clear();
    label nOutside = 0;
    forAll(owner, i)
    {
        if (owner[i] >= 0)
        {
            sent_[owner[i]].append(i);
        }
        else if (p.cell[i] < 0)
        {
            ++nOutside;
        }
    }

    PstreamBuffers moves(Pstream::commsTypes::nonBlocking);
    nSent_ = 0;
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (sent_[proci].size())
        {
            UOPstream os(proci, moves);
            p.writeDEMData(os, sent_[proci], plan);
            nSent_ += sent_[proci].size();
        }
    }
    labelList movesSizes;
    moves.finishedSends(movesSizes);

    nReceived_ = 0;
    for (label proci = 0; proci < nProcs; ++proci)
    {
        received_[proci].clear();
        if (!movesSizes[proci]) continue;
        UIPstream is(proci, moves);
        const label n0 = p.size();
        p.appendDEMData(is, plan);
        received_[proci] = identity(p.size() - n0, n0);
        nReceived_ += p.size() - n0;
    }

    // Locate the arrivals (hints from step 1 make this cheap)
    if (nReceived_)
    {
        particleData arrivals;
        const labelList slots(identity(nReceived_, nDEMLocal_));
        arrivals.position = pointField(UIndirectList<point>(p.position, slots));
        arrivals.id = labelList(UIndirectList<label>(p.id, slots));
        arrivals.cell.setSize(nReceived_, -1);
        locate.locate(arrivals);
        forAll(slots, k)
        {
            p.cell[slots[k]] = arrivals.cell[k];
        }
    }

    // Bytes of the DEM data moved: position and id always, plus the rest
    label perParticle = 3*sizeof(scalar) + sizeof(label);
    if (plan.has(quantity::velocity)) perParticle += 3*sizeof(scalar);
    if (plan.has(quantity::radius)) perParticle += sizeof(scalar);
    if (plan.has(quantity::density)) perParticle += sizeof(scalar);
    if (plan.has(quantity::angularVelocity)) perParticle += 3*sizeof(scalar);
    bytesSent_ += nSent_*perParticle;

    return returnReduce(nOutside, sumOp<label>());
}


void Foam::foamDEM::particleTransfer::scatterBack
(
    particleData& p,
    const exchangePlan& plan
)
{
    const label nProcs = Pstream::nProcs();

    PstreamBuffers results(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        const labelList& slots = received_[proci];
        if (slots.size())
        {
            UOPstream os(proci, results);
            p.writeResults(os, slots.first(), slots.size());
            bytesSent_ += slots.size()*(11*sizeof(scalar));
        }
    }
    labelList resultsSizes;
    results.finishedSends(resultsSizes);

    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (!resultsSizes[proci]) continue;
        UIPstream is(proci, results);
        p.readResults(is, sent_[proci]);
    }

    p.resize(nDEMLocal_, plan);
}
