#include "particleTransfer.H"
#include "neighbourExchange.H"

namespace
{
bool overlapsAny
(
    const Foam::boundBox& b,
    const Foam::List<Foam::boundBox>& boxes
)
{
    for (const Foam::boundBox& c : boxes)
    {
        if (b.overlaps(c)) return true;
    }
    return false;
}
}


Foam::foamDEM::particleTransfer::particleTransfer
(
    const fvMesh& mesh,
    const List<boundBox>& reach
)
:
    mesh_(mesh),
    reach_(reach),
    procBoxes_(Pstream::nProcs()),
    nDEMLocal_(0),
    bytesSent_(0),
    nSent_(0),
    nReceived_(0),
    nAllRanks_(0)
{
    // A slightly inflated box, so that particles on a processor face are
    // asked on both sides
    treeBoundBox box(mesh.points());
    const scalar tol = 1e-6*max(box.mag(), SMALL);
    box.min() -= vector::uniform(tol);
    box.max() += vector::uniform(tol);
    const label me = Pstream::myProcNo();
    procBoxes_[me] = box;
    Pstream::gatherList(procBoxes_);
    Pstream::scatterList(procBoxes_);

    meshBox_ = treeBoundBox(procBoxes_[0].min(), procBoxes_[0].max());
    for (const treeBoundBox& b : procBoxes_)
    {
        meshBox_.add(b);
    }

    // Every rank's DEM reach, once
    List<List<boundBox>> reaches(Pstream::nProcs());
    reaches[me] = reach_;
    Pstream::gatherList(reaches);
    Pstream::scatterList(reaches);

    DynamicList<label> to, from, all;
    forAll(procBoxes_, proci)
    {
        if (proci == me) continue;
        all.append(proci);
        if (overlapsAny(procBoxes_[proci], reaches[me])) to.append(proci);
        if (overlapsAny(procBoxes_[me], reaches[proci])) from.append(proci);
    }
    sendProcs_.transfer(to);
    recvProcs_.transfer(from);
    allProcs_.transfer(all);
}


void Foam::foamDEM::particleTransfer::ask
(
    const particleData& p,
    const labelList& procs,
    labelListList& asked
) const
{
    asked.setSize(procs.size());
    for (labelList& a : asked) a.clear();
    List<DynamicList<label>> lists(procs.size());
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0) continue;
        forAll(procs, k)
        {
            if (procBoxes_[procs[k]].contains(p.position[i]))
            {
                lists[k].append(i);
            }
        }
    }
    forAll(lists, k)
    {
        asked[k].transfer(lists[k]);
    }
}


Foam::label Foam::foamDEM::particleTransfer::gather
(
    particleData& p,
    locateModel& locate,
    const exchangePlan& plan
)
{
    nDEMLocal_ = p.size();
    bytesSent_ = 0;

    // 1. Ask the neighbours whose box holds a particle that we do not
    //    contain. A particle outside this rank's DEM reach but in another
    //    rank's box (a stray) makes this step exchange with all ranks.
    labelListList asked;
    ask(p, sendProcs_, asked);
    label nStray = 0;
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0) continue;
        const point& x = p.position[i];
        // Within the reach, only neighbours' boxes can hold it (that is how
        // the neighbours were chosen)
        if (overlapsAny(boundBox(x, x), reach_) || !meshBox_.contains(x))
        {
            continue;
        }
        for (const label proci : allProcs_)
        {
            if (procBoxes_[proci].contains(x))
            {
                ++nStray;
                break;
            }
        }
    }
    if (returnReduce(nStray, sumOp<label>()) > 0)
    {
        if (nStray && !nAllRanks_)
        {
            Pout<< "foamDEM exchange: " << nStray << " particle(s) outside"
                << " the DEM reach of this rank at t = "
                << mesh_.time().timeName()
                << " s: this step exchanges with all ranks (such steps are"
                << " counted in the summary at the end)" << endl;
        }
        to_ = allProcs_;
        from_ = allProcs_;
        ++nAllRanks_;
        ask(p, to_, asked);
    }
    else
    {
        to_ = sendProcs_;
        from_ = recvProcs_;
    }

    neighbourExchange queries(to_, from_);
    forAll(to_, k)
    {
        if (asked[k].size())
        {
            queries.out(k)
                << pointField(UIndirectList<point>(p.position, asked[k]))
                << labelList(UIndirectList<label>(p.id, asked[k]));
        }
    }
    queries.exchange();
    bytesSent_ += queries.bytesSent();

    // Answer: which of the asked positions lie in this rank's mesh
    neighbourExchange answers(from_, to_);
    forAll(from_, k)
    {
        if (!queries.received(k)) continue;
        particleData q;
        queries.in(k) >> q.position >> q.id;
        q.cell.setSize(q.position.size(), -1);
        locate.locate(q);

        boolList found(q.size());
        forAll(found, j)
        {
            found[j] = q.cell[j] >= 0;
        }
        answers.out(k) << found;
    }
    answers.exchange();
    bytesSent_ += answers.bytesSent();

    // 2. Each particle goes to the lowest rank that contains it (to_ is
    //    in rank order, so the lowest slot)
    labelList owner(p.size(), -1);
    forAll(to_, k)
    {
        if (!answers.received(k)) continue;
        boolList found;
        answers.in(k) >> found;
        forAll(found, j)
        {
            const label i = asked[k][j];
            if (found[j] && owner[i] < 0)
            {
                owner[i] = k;
            }
        }
    }

    sent_.setSize(to_.size());
    for (labelList& s : sent_) s.clear();
    label nOutside = 0;
    {
        List<DynamicList<label>> lists(to_.size());
        forAll(owner, i)
        {
            if (owner[i] >= 0)
            {
                lists[owner[i]].append(i);
            }
            else if (p.cell[i] < 0)
            {
                ++nOutside;
            }
        }
        forAll(lists, k)
        {
            sent_[k].transfer(lists[k]);
        }
    }

    neighbourExchange moves(to_, from_);
    nSent_ = 0;
    forAll(to_, k)
    {
        if (sent_[k].size())
        {
            p.writeDEMData(moves.out(k), sent_[k], plan);
            nSent_ += sent_[k].size();
        }
    }
    moves.exchange();
    bytesSent_ += moves.bytesSent();

    nReceived_ = 0;
    received_.setSize(from_.size());
    forAll(from_, k)
    {
        received_[k].clear();
        if (!moves.received(k)) continue;
        const label n0 = p.size();
        p.appendDEMData(moves.in(k), plan);
        received_[k] = identity(p.size() - n0, n0);
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

    return returnReduce(nOutside, sumOp<label>());
}


void Foam::foamDEM::particleTransfer::scatterBack
(
    particleData& p,
    const exchangePlan& plan
)
{
    neighbourExchange results(from_, to_);
    forAll(from_, k)
    {
        const labelList& slots = received_[k];
        if (slots.size())
        {
            p.writeResults(results.out(k), slots.first(), slots.size());
        }
    }
    results.exchange();
    bytesSent_ += results.bytesSent();

    forAll(to_, k)
    {
        if (results.received(k))
        {
            p.readResults(results.in(k), sent_[k]);
        }
    }

    p.resize(nDEMLocal_, plan);
}
