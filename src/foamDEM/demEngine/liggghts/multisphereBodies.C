#include "multisphereBodies.H"

#include <mpi.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "lammps.h"
#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "update.h"
#include "fix_multisphere.h"
#include "multisphere.h"
#include "custom_value_tracker.h"
#include "scalar_container.h"
#include "vector_container.h"

namespace
{
    constexpr int nCol = 28;

    const char* columns =
        "tag type mass x y z vx vy vz q0 q1 q2 q3 exx exy exz eyx eyy eyz"
        " ezx ezy ezz Lx Ly Lz wx wy wz";

    // The body properties of fix multisphere's data, by name
    struct bodyArrays
    {
        int* type;
        double* mass;
        double** xcm;
        double** vcm;
        double** quat;
        double** ex;
        double** ey;
        double** ez;
        double** angmom;
        double** omega;
        double** fcm;
        double** torque;
        double** dragforce;
        double** hdtorque;
    };

    template<class Container>
    Container& property(LAMMPS_NS::Multisphere& data, const char* name)
    {
        Container* c = data.prop().getElementProperty<Container>(name);
        if (!c)
        {
            throw std::runtime_error
            (
                std::string("fix multisphere has no body property ") + name
            );
        }
        return *c;
    }

    bodyArrays arrays(LAMMPS_NS::Multisphere& d)
    {
        using V3 = LAMMPS_NS::VectorContainer<double, 3>;
        bodyArrays a;
        a.type = property<LAMMPS_NS::ScalarContainer<int>>(d, "clumptype").begin();
        a.mass = property<LAMMPS_NS::ScalarContainer<double>>(d, "masstotal").begin();
        a.xcm = property<V3>(d, "xcm").begin();
        a.vcm = property<V3>(d, "vcm").begin();
        a.quat = property<LAMMPS_NS::VectorContainer<double, 4>>(d, "quat").begin();
        a.ex = property<V3>(d, "ex_space").begin();
        a.ey = property<V3>(d, "ey_space").begin();
        a.ez = property<V3>(d, "ez_space").begin();
        a.angmom = property<V3>(d, "angmom").begin();
        a.omega = property<V3>(d, "omega").begin();
        a.fcm = property<V3>(d, "fcm").begin();
        a.torque = property<V3>(d, "torque").begin();
        a.dragforce = property<V3>(d, "dragforce_cm").begin();
        a.hdtorque = property<V3>(d, "hdtorque_cm").begin();
        return a;
    }

    void requireNonPeriodic(const LAMMPS_NS::Domain& domain)
    {
        if (domain.xperiodic || domain.yperiodic || domain.zperiodic)
        {
            throw std::runtime_error
            (
                "body states are only carried in a non-periodic domain"
                " (boundary f or m in every direction)"
            );
        }
    }

    double dot(const double* a, const double* b)
    {
        return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
    }
}


std::string Foam::foamDEM::bodyStateFile(const std::string& restart)
{
    const std::string ext(".restart");
    if
    (
        restart.size() > ext.size()
     && restart.compare(restart.size() - ext.size(), ext.size(), ext) == 0
    )
    {
        return restart.substr(0, restart.size() - ext.size()) + ".bodies";
    }
    return restart + ".bodies";
}


long Foam::foamDEM::writeBodyStates
(
    LAMMPS_NS::LAMMPS& lmp,
    LAMMPS_NS::FixMultisphere& ms,
    const std::string& file
)
{
    requireNonPeriodic(*lmp.domain);
    LAMMPS_NS::Multisphere& d = ms.data();
    const bodyArrays a = arrays(d);
    const int n = d.n_body();

    std::vector<double> local(size_t(n)*nCol);
    for (int b = 0; b < n; ++b)
    {
        double* r = &local[size_t(b)*nCol];
        r[0] = d.tag(b);
        r[1] = a.type[b];
        r[2] = a.mass[b];
        for (int k = 0; k < 3; ++k)
        {
            r[3 + k] = a.xcm[b][k];
            r[6 + k] = a.vcm[b][k];
            r[13 + k] = a.ex[b][k];
            r[16 + k] = a.ey[b][k];
            r[19 + k] = a.ez[b][k];
            r[22 + k] = a.angmom[b][k];
            r[25 + k] = a.omega[b][k];
        }
        for (int k = 0; k < 4; ++k) r[9 + k] = a.quat[b][k];
    }

    MPI_Comm world = lmp.world;
    int rank = 0, nProcs = 1;
    MPI_Comm_rank(world, &rank);
    MPI_Comm_size(world, &nProcs);
    const int count = int(local.size());
    std::vector<int> counts(nProcs), offsets(nProcs, 0);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
    std::vector<double> all;
    if (rank == 0)
    {
        for (int p = 1; p < nProcs; ++p)
        {
            offsets[p] = offsets[p - 1] + counts[p - 1];
        }
        all.resize(size_t(offsets[nProcs - 1]) + counts[nProcs - 1]);
    }
    MPI_Gatherv
    (
        local.data(), count, MPI_DOUBLE,
        all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, world
    );

    long nAll = 0;
    int ok = 1;
    std::string error;
    if (rank == 0)
    {
        nAll = long(all.size()/nCol);
        // sorted by tag
        std::vector<long> order(nAll);
        for (long i = 0; i < nAll; ++i) order[i] = i;
        std::sort
        (
            order.begin(), order.end(),
            [&all](long i, long j) { return all[i*nCol] < all[j*nCol]; }
        );
        // written under another name and renamed: never a partial file
        const std::string part(file + ".part");
        std::FILE* f = std::fopen(part.c_str(), "wb");
        if (!f)
        {
            ok = 0;
            error = "cannot write " + part;
        }
        else
        {
            std::fprintf
            (
                f, "foamDEMBodies 1\nstep %lld bodies %ld columns %d\n%s\n",
                static_cast<long long>(lmp.update->ntimestep), nAll, nCol,
                columns
            );
            for (long i : order)
            {
                if (std::fwrite(&all[i*nCol], sizeof(double), nCol, f) != size_t(nCol))
                {
                    ok = 0;
                }
            }
            if (std::fclose(f) != 0) ok = 0;
            if (!ok) error = "cannot write " + part + " (disk full?)";
            else if (std::rename(part.c_str(), file.c_str()) != 0)
            {
                ok = 0;
                error = "cannot rename " + part + " to " + file;
            }
        }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok)
    {
        throw std::runtime_error
        (
            rank == 0 ? error : "rank 0 could not write " + file
        );
    }
    MPI_Bcast(&nAll, 1, MPI_LONG, 0, world);
    return nAll;
}


long Foam::foamDEM::readBodyStates
(
    LAMMPS_NS::LAMMPS& lmp,
    LAMMPS_NS::FixMultisphere& ms,
    const std::string& file
)
{
    if (lmp.comm->nprocs != 1)
    {
        throw std::runtime_error
        (
            "body states are set on one rank only (every sphere with its"
            " body); run this stage with one process"
        );
    }
    requireNonPeriodic(*lmp.domain);

    // The file
    std::ifstream is(file, std::ios::binary);
    if (!is)
    {
        throw std::runtime_error("cannot read the body states " + file);
    }
    std::string magic, line2, names;
    std::getline(is, magic);
    std::getline(is, line2);
    std::getline(is, names);
    long long step = -1;
    long nFile = -1;
    int cols = -1;
    {
        std::istringstream h(line2);
        std::string w1, w2, w3;
        h >> w1 >> step >> w2 >> nFile >> w3 >> cols;
        if
        (
            magic != "foamDEMBodies 1" || !h || w1 != "step" || w2 != "bodies"
         || w3 != "columns" || cols != nCol || names != columns || nFile < 0
        )
        {
            throw std::runtime_error
            (
                file + " is not a foamDEM body-state file (version 1, "
                + std::to_string(nCol) + " columns)"
            );
        }
    }
    std::vector<double> rows(size_t(nFile)*nCol);
    is.read(reinterpret_cast<char*>(rows.data()), rows.size()*sizeof(double));
    if (!is || is.peek() != std::char_traits<char>::eof())
    {
        throw std::runtime_error
        (
            file + ": its size does not match its " + std::to_string(nFile)
          + " bodies (a cut-off file?)"
        );
    }

    // The bodies held now, and the file's, each type in the order of
    // their tags
    LAMMPS_NS::Multisphere& d = ms.data();
    const bodyArrays a = arrays(d);
    const int n = d.n_body();
    std::map<int, std::vector<int>> held;
    std::map<int, std::vector<long>> stored;
    {
        std::vector<int> byTag(n);
        for (int b = 0; b < n; ++b) byTag[b] = b;
        std::sort
        (
            byTag.begin(), byTag.end(),
            [&d](int i, int j) { return d.tag(i) < d.tag(j); }
        );
        for (int b : byTag) held[a.type[b]].push_back(b);
        for (long i = 0; i < nFile; ++i)   // the file is sorted by tag
        {
            stored[int(rows[i*nCol + 1])].push_back(i);
        }
    }
    {
        std::ostringstream counts;
        bool same = held.size() == stored.size();
        for (const auto& t : stored)
        {
            const auto h = held.find(t.first);
            const size_t nh = h == held.end() ? 0 : h->second.size();
            counts << " type " << t.first << ": " << t.second.size()
                << " in the file, " << nh << " held;";
            same = same && nh == t.second.size();
        }
        if (!same)
        {
            throw std::runtime_error
            (
                file + ": the bodies held are not those of the file (the"
                " same multisphere types, as many of each, are needed):"
              + counts.str()
            );
        }
    }

    // Each sphere's place in its body's frame, from the bodies as they are
    LAMMPS_NS::Atom& atom = *lmp.atom;
    const int nlocal = atom.nlocal;
    std::vector<double> local(size_t(nlocal)*3, 0.0);
    std::vector<int> body(nlocal, -1);
    for (int i = 0; i < nlocal; ++i)
    {
        const int tag = ms.belongs_to(i);
        const int b = tag >= 0 ? d.map(tag) : -1;
        if (tag >= 0 && b < 0)
        {
            throw std::runtime_error
            (
                "a sphere of body " + std::to_string(tag) + " has no body"
                " on this rank"
            );
        }
        body[i] = b;
        if (b < 0) continue;
        const double r[3] =
        {
            atom.x[i][0] - a.xcm[b][0],
            atom.x[i][1] - a.xcm[b][1],
            atom.x[i][2] - a.xcm[b][2]
        };
        local[3*i] = dot(a.ex[b], r);
        local[3*i + 1] = dot(a.ey[b], r);
        local[3*i + 2] = dot(a.ez[b], r);
    }

    // The bodies from the file
    for (const auto& t : stored)
    {
        const std::vector<int>& hb = held[t.first];
        for (size_t k = 0; k < hb.size(); ++k)
        {
            const int b = hb[k];
            const double* r = &rows[size_t(t.second[k])*nCol];
            if (std::abs(r[2] - a.mass[b]) > 1e-9*std::abs(r[2]))
            {
                std::ostringstream os;
                os.precision(10);
                os  << file << ": a body of type " << t.first << " has mass "
                    << r[2] << " in the file and " << a.mass[b] << " here"
                    << " (another template?)";
                throw std::runtime_error(os.str());
            }
            for (int c = 0; c < 3; ++c)
            {
                a.xcm[b][c] = r[3 + c];
                a.vcm[b][c] = r[6 + c];
                a.ex[b][c] = r[13 + c];
                a.ey[b][c] = r[16 + c];
                a.ez[b][c] = r[19 + c];
                a.angmom[b][c] = r[22 + c];
                a.omega[b][c] = r[25 + c];
                a.fcm[b][c] = a.torque[b][c] = 0;
                a.dragforce[b][c] = a.hdtorque[b][c] = 0;
            }
            for (int c = 0; c < 4; ++c) a.quat[b][c] = r[9 + c];
        }
    }

    // Each sphere with its body (as fix multisphere's set_xv places them)
    for (int i = 0; i < nlocal; ++i)
    {
        const int b = body[i];
        if (b < 0) continue;
        const double* p = &local[3*i];
        double r[3];
        for (int c = 0; c < 3; ++c)
        {
            r[c] = a.ex[b][c]*p[0] + a.ey[b][c]*p[1] + a.ez[b][c]*p[2];
        }
        const double* w = a.omega[b];
        atom.v[i][0] = w[1]*r[2] - w[2]*r[1] + a.vcm[b][0];
        atom.v[i][1] = w[2]*r[0] - w[0]*r[2] + a.vcm[b][1];
        atom.v[i][2] = w[0]*r[1] - w[1]*r[0] + a.vcm[b][2];
        for (int c = 0; c < 3; ++c)
        {
            atom.x[i][c] = a.xcm[b][c] + r[c];
            atom.omega[i][c] = w[c];
        }
    }
    return long(step);
}


// ************************************************************************* //
