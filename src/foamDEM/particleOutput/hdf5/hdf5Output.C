#include "hdf5Output.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <mpi.h>
#include <hdf5.h>
#include <sstream>
#include <vector>

namespace Foam
{
namespace foamDEM
{
    defineTypeNameAndDebug(hdf5Output, 0);
    addToRunTimeSelectionTable(particleOutput, hdf5Output, dictionary);
}
}


namespace
{
    //- Does every rank report success? (collective)
    bool allRanks(bool ok)
    {
        int local = ok ? 1 : 0, global = 0;
        MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        return global == 1;
    }

    //- Datasets the XDMF lists as attributes, in this order; position is
    //  the geometry
    const char* const attributeNames[] =
    {
        "velocity", "diameter", "id", "type", "force", "angularVelocity",
        "orientation", "voidFraction", "Kp", "Kpf", "Us"
    };

    std::string fmt(double x)
    {
        std::ostringstream os;
        os.precision(17);
        os << x;
        return os.str();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::foamDEM::hdf5Output::hdf5Output
(
    const fvMesh& mesh,
    const word& cloudName,
    const dictionary& coeffs
)
:
    particleOutput(mesh, cloudName),
    couplingFields_(coeffs.getOrDefault("couplingFields", false)),
    scanned_(false)
{
    Info<< "    particle output hdf5: " << directory().c_str() << '/'
        << cloudName_.c_str() << "_<time>.h5 and " << cloudName_.c_str()
        << ".xdmf"
        << (couplingFields_ ? ", with the coupling fields" : "") << endl;
}


// * * * * * * * * * * * * * * * Member functions  * * * * * * * * * * * * * //

Foam::fileName Foam::foamDEM::hdf5Output::directory() const
{
    return mesh_.time().globalPath()/"hdf5";
}


Foam::fileName Foam::foamDEM::hdf5Output::h5Name(const word& timeName) const
{
    return cloudName_ + "_" + timeName + ".h5";
}


void Foam::foamDEM::hdf5Output::addRequirements(exchangePlan& plan) const
{
    const word who("hdf5Output");
    needParticles(plan, who);
    plan.need(quantity::type, who);
}


void Foam::foamDEM::hdf5Output::write
(
    const particleData& p,
    const exchangePlan& plan
)
{
    const word timeName(mesh_.time().timeName());
    const scalar time = mesh_.time().value();
    const fileName path(directory()/h5Name(timeName));

    int mpiUp = 0;
    MPI_Initialized(&mpiUp);
    if (!mpiUp)
    {
        // The DEM engine starts MPI, also in a serial run
        FatalErrorInFunction
            << "particleOutput hdf5 needs MPI, which the DEM engine has not"
            << " started" << exit(FatalError);
    }

    // The particles in this rank's mesh, and this rank's rows of the file
    DynamicList<label> rows(p.size());
    forAll(p.cell, i)
    {
        if (p.cell[i] >= 0) rows.append(i);
    }
    long long nLocal = rows.size(), offset = 0, nTotal = 0;
    MPI_Exscan(&nLocal, &offset, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    if (Pstream::myProcNo() == 0) offset = 0;   // undefined on rank 0
    MPI_Allreduce(&nLocal, &nTotal, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);

    // Stop every rank, naming the step, if it failed on any
    // (a rank where it worked waits a little first, so that the failed
    // rank's message is out before anyone's MPI_Abort ends the run)
    auto check = [&](bool ok, const std::string& step)
    {
        if (!allRanks(ok))
        {
            if (ok)
            {
                Foam::sleep(2);
                FatalErrorInFunction
                    << "HDF5 particle output: another rank failed, for "
                    << path << " (this rank: " << step.c_str() << ")"
                    << exit(FatalError);
            }
            FatalErrorInFunction
                << "HDF5 particle output: " << step.c_str() << " failed for "
                << path << " on this rank (HDF5's message above, if any)"
                << exit(FatalError);
        }
    };

    if (Pstream::master())
    {
        mkDir(directory());
    }
    check(!Pstream::master() || isDir(directory()), "creating the directory");

    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    bool ok = fapl >= 0
        && H5Pset_fapl_mpio(fapl, MPI_COMM_WORLD, MPI_INFO_NULL) >= 0;
    check(ok, "setting up MPI-IO");
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    check(file >= 0, "creating the file");

    const hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
    check
    (
        dxpl >= 0 && H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE) >= 0,
        "setting up collective writes"
    );

    // The first dataset whose write failed on this rank
    std::string writeError;

    // One dataset of nTotal x nComp values (nComp 1: a 1-D dataset), this
    // rank's rows from 'offset'; every rank calls it, empty ones select none
    auto writeDataset = [&]
    (
        const char* name,
        hid_t memType,
        hid_t fileType,
        hsize_t nComp,
        const void* data
    )
    {
        const int rank = nComp > 1 ? 2 : 1;
        const hsize_t dims[2] = {hsize_t(nTotal), nComp};
        const hsize_t start[2] = {hsize_t(offset), 0};
        const hsize_t count[2] = {hsize_t(nLocal), nComp};
        const hsize_t one[2] = {1, nComp};

        const hid_t fspace = H5Screate_simple(rank, dims, nullptr);
        const hid_t dset = fspace < 0 ? -1
          : H5Dcreate2
            (
                file, name, fileType, fspace,
                H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT
            );
        const hid_t mspace =
            H5Screate_simple(rank, nLocal ? count : one, nullptr);
        bool ok = fspace >= 0 && dset >= 0 && mspace >= 0;
        if (ok && nLocal)
        {
            ok = H5Sselect_hyperslab
            (
                fspace, H5S_SELECT_SET, start, nullptr, count, nullptr
            ) >= 0;
        }
        else if (ok)
        {
            ok = H5Sselect_none(fspace) >= 0 && H5Sselect_none(mspace) >= 0;
        }
        // Agree before the collective write: a rank that cannot take part
        // would leave the others waiting in it
        check
        (
            ok && writeError.empty(),
            writeError.empty()
          ? std::string("creating dataset ") + name
          : "writing dataset " + writeError
        );
        // No particles on any rank: the empty dataset has no storage to
        // write to (HDF5 refuses the write); the same on every rank
        static const double dummy[9] = {};
        ok = nTotal == 0 || H5Dwrite
        (
            dset, memType, mspace, fspace, dxpl, nLocal ? data : dummy
        ) >= 0;
        H5Sclose(mspace);
        H5Dclose(dset);
        H5Sclose(fspace);
        // Checked with the next step that needs the ranks to agree
        if (!ok && writeError.empty()) writeError = name;
    };

    // Gather this rank's rows of a per-particle quantity and write it
    auto writeScalars = [&](const char* name, auto value)
    {
        std::vector<double> buf(rows.size());
        forAll(rows, k) buf[k] = value(rows[k]);
        writeDataset(name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, 1, buf.data());
    };
    auto writeLabels = [&](const char* name, const labelList& f)
    {
        std::vector<int> buf(rows.size());
        forAll(rows, k) buf[k] = f[rows[k]];
        writeDataset(name, H5T_NATIVE_INT, H5T_STD_I32LE, 1, buf.data());
    };
    auto writeVectors = [&](const char* name, auto value)
    {
        std::vector<double> buf(3*rows.size());
        forAll(rows, k)
        {
            const vector v(value(rows[k]));
            for (direction d = 0; d < 3; ++d) buf[3*k + d] = v[d];
        }
        writeDataset(name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, 3, buf.data());
    };

    writeVectors("position", [&](label i) { return p.position[i]; });
    writeVectors("velocity", [&](label i) { return p.velocity[i]; });
    writeScalars("diameter", [&](label i) { return p.diameter(i); });
    writeLabels("id", p.id);
    writeLabels("type", p.type);
    writeVectors("force", [&](label i) { return p.fluidForce[i]; });
    if (plan.has(quantity::angularVelocity))
    {
        writeVectors
        (
            "angularVelocity", [&](label i) { return p.angularVelocity[i]; }
        );
    }
    if (plan.has(quantity::orientation))
    {
        std::vector<double> buf(9*rows.size());
        forAll(rows, k)
        {
            const tensor& t = p.orientation[rows[k]];
            for (direction c = 0; c < 9; ++c) buf[9*k + c] = t[c];
        }
        writeDataset
        (
            "orientation", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, 9, buf.data()
        );
    }
    if (couplingFields_)
    {
        const volScalarField& Kpf = mesh_.lookupObject<volScalarField>("Ksl");
        const volVectorField& Us = mesh_.lookupObject<volVectorField>("Us");
        writeScalars("voidFraction", [&](label i) { return p.voidFraction[i]; });
        writeScalars("Kp", [&](label i) { return p.dragCoeff[i]; });
        writeScalars("Kpf", [&](label i) { return Kpf[p.cell[i]]; });
        writeVectors("Us", [&](label i) { return Us[p.cell[i]]; });
    }
    H5Pclose(dxpl);
    check(writeError.empty(), "writing dataset " + writeError);

    // Attributes on the root group (collective, the same on every rank)
    auto writeAttribute = [&](const char* name, hid_t type, const void* v)
    {
        const hid_t space = H5Screate(H5S_SCALAR);
        const hid_t attr = space < 0 ? -1
          : H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
        const bool ok = attr >= 0 && H5Awrite(attr, type, v) >= 0;
        if (attr >= 0) H5Aclose(attr);
        if (space >= 0) H5Sclose(space);
        check(ok, std::string("writing attribute ") + name);
    };
    const double t = time;
    writeAttribute("time", H5T_NATIVE_DOUBLE, &t);
    writeAttribute("nParticles", H5T_NATIVE_LLONG, &nTotal);

    check(H5Fclose(file) >= 0, "closing the file");

    std::string error;
    if (Pstream::master())
    {
        error = updateXdmf(timeName, time);
    }
    check(error.empty(), "the XDMF file: " + error);
}


bool Foam::foamDEM::hdf5Output::readGrid
(
    const fileName& path,
    const fileName& relative,
    scalar& time,
    std::string& grid
)
{
    // Quiet: a foreign or broken file is skipped with a warning
    H5E_auto2_t func;
    void* data;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);

    bool ok = false;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file >= 0)
    {
        const hid_t attr = H5Aopen(file, "time", H5P_DEFAULT);
        double t = 0;
        ok = attr >= 0 && H5Aread(attr, H5T_NATIVE_DOUBLE, &t) >= 0;
        if (attr >= 0) H5Aclose(attr);
        time = t;

        // Shape and kind of a dataset; false if it is not there
        auto shape = [&](const char* name, hsize_t& n, hsize_t& nComp,
                         bool& isInt)
        {
            if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return false;
            const hid_t dset = H5Dopen2(file, name, H5P_DEFAULT);
            if (dset < 0) return false;
            const hid_t space = H5Dget_space(dset);
            hsize_t dims[2] = {0, 1};
            const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
            const hid_t type = H5Dget_type(dset);
            isInt = H5Tget_class(type) == H5T_INTEGER;
            H5Tclose(type);
            H5Sclose(space);
            H5Dclose(dset);
            n = dims[0];
            nComp = rank > 1 ? dims[1] : 1;
            return rank >= 1;
        };
        auto item = [&](const char* name, hsize_t n, hsize_t nComp, bool isInt)
        {
            std::string dims = std::to_string(n);
            if (nComp > 1) dims += " " + std::to_string(nComp);
            return "<DataItem Dimensions=\"" + dims + "\" NumberType=\""
                + (isInt ? "Int\" Precision=\"4" : "Float\" Precision=\"8")
                + "\" Format=\"HDF\">" + relative + ":/" + name
                + "</DataItem>";
        };

        hsize_t n = 0, nComp = 0;
        bool isInt = false;
        ok = ok && shape("position", n, nComp, isInt) && nComp == 3;
        if (ok)
        {
            const std::string N(std::to_string(n));
            std::string g =
                "   <Grid Name=\"particles\" GridType=\"Uniform\">\n"
                "    <Time Value=\"" + fmt(t) + "\"/>\n"
                "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\""
              + N + "\" NodesPerElement=\"1\"/>\n"
                "    <Geometry GeometryType=\"XYZ\">\n     "
              + item("position", n, 3, false) + "\n    </Geometry>\n";
            for (const char* name : attributeNames)
            {
                hsize_t na = 0, nc = 0;
                bool ai = false;
                if (!shape(name, na, nc, ai) || na != n) continue;
                const char* kind =
                    nc == 1 ? "Scalar" : nc == 3 ? "Vector" : "Tensor";
                g += "    <Attribute Name=\"" + std::string(name)
                   + "\" AttributeType=\"" + kind + "\" Center=\"Node\">\n     "
                   + item(name, na, nc, ai) + "\n    </Attribute>\n";
            }
            grid = g + "   </Grid>\n";
        }
        H5Fclose(file);
    }

    H5Eset_auto2(H5E_DEFAULT, func, data);
    return ok;
}


std::string Foam::foamDEM::hdf5Output::updateXdmf
(
    const word& timeName,
    scalar time
)
{
    const fileName dir(directory());
    const scalar tol = 1e-9*max(mag(time), mesh_.time().deltaTValue());

    // A continued run: the files of earlier times
    if (!scanned_)
    {
        scanned_ = true;
        const std::string prefix(cloudName_ + "_");
        for (const fileName& f : readDir(dir, fileName::FILE, false))
        {
            if (f.ext() != "h5" || f.compare(0, prefix.size(), prefix) != 0)
            {
                continue;
            }
            scalar t = 0;
            std::string grid;
            if (!readGrid(dir/f, f, t, grid))
            {
                WarningInFunction
                    << "Cannot read " << dir/f << ": not listed in "
                    << cloudName_ << ".xdmf" << endl;
                continue;
            }
            if (t < time - tol)
            {
                grids_[t] = grid;
            }
        }
    }

    // The file just written
    const fileName h5(h5Name(timeName));
    scalar t = 0;
    std::string grid;
    if (!readGrid(dir/h5, h5, t, grid))
    {
        return "cannot read back " + dir/h5;
    }
    // Times from a longer earlier run are dropped as the run passes them
    grids_.erase(grids_.lower_bound(time - tol), grids_.end());
    grids_[time] = grid;

    const fileName xdmf(dir/(cloudName_ + ".xdmf"));
    const fileName tmp(xdmf + ".tmp");
    {
        OFstream os(tmp);
        os  << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"2.0\">\n"
            << " <Domain>\n"
            << "  <Grid Name=\"" << cloudName_.c_str()
            << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
        for (const auto& entry : grids_)
        {
            os  << entry.second.c_str();
        }
        os  << "  </Grid>\n"
            << " </Domain>\n"
            << "</Xdmf>\n";
        if (!os.good())
        {
            return "cannot write " + tmp;
        }
    }
    if (!mv(tmp, xdmf))
    {
        return "cannot rename " + tmp + " to " + xdmf;
    }
    return std::string();
}
