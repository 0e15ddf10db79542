#include "neighbourExchange.H"
#include "UPstream.H"
#include "UIPstream.H"
#include "UOPstream.H"

Foam::foamDEM::neighbourExchange::neighbourExchange
(
    const labelUList& to,
    const labelUList& from
)
:
    to_(to),
    from_(from),
    out_(to.size()),
    sendSizes_(to.size(), 0),
    recvSizes_(from.size(), 0),
    recvBufs_(from.size()),
    in_(from.size()),
    bytesSent_(0)
{}


Foam::Ostream& Foam::foamDEM::neighbourExchange::out(label k)
{
    if (!out_.set(k))
    {
        out_.set(k, new OListStream(IOstream::BINARY));
    }
    return out_[k];
}


void Foam::foamDEM::neighbourExchange::exchange()
{
    const UPstream::commsTypes nb = UPstream::commsTypes::nonBlocking;
    const label comm = UPstream::worldComm;

    // 1. Sizes: one label to every rank of to_, one from every rank of from_
    forAll(to_, k)
    {
        sendSizes_[k] = out_.set(k) ? label(out_[k].size()) : 0;
    }
    label start = UPstream::nRequests();
    forAll(from_, k)
    {
        UIPstream::read
        (
            nb, from_[k], reinterpret_cast<char*>(&recvSizes_[k]),
            sizeof(label), tag, comm
        );
    }
    forAll(to_, k)
    {
        UOPstream::write
        (
            nb, to_[k], reinterpret_cast<const char*>(&sendSizes_[k]),
            sizeof(label), tag, comm
        );
        bytesSent_ += sizeof(label);
    }
    UPstream::waitRequests(start);

    // 2. The non-empty buffers
    start = UPstream::nRequests();
    forAll(from_, k)
    {
        if (recvSizes_[k] > 0)
        {
            recvBufs_[k].setSize(recvSizes_[k]);
            UIPstream::read
            (
                nb, from_[k], recvBufs_[k].data(), recvSizes_[k], tag, comm
            );
        }
    }
    forAll(to_, k)
    {
        if (sendSizes_[k] > 0)
        {
            UOPstream::write
            (
                nb, to_[k], out_[k].list().cdata(), sendSizes_[k], tag, comm
            );
            bytesSent_ += sendSizes_[k];
        }
    }
    UPstream::waitRequests(start);
}


Foam::Istream& Foam::foamDEM::neighbourExchange::in(label k)
{
    if (!in_.set(k))
    {
        in_.set(k, new UIListStream(recvBufs_[k], IOstream::BINARY));
    }
    return in_[k];
}
