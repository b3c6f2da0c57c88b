#include "fem/MeshReader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

#include <gmsh.h>

namespace flexehd::fem {
namespace {

namespace fs = std::filesystem;

// Gmsh keeps global state: one initialisation per process, one model at a time.
std::mutex& gmshMutex() {
    static std::mutex m;
    return m;
}

// A fresh Gmsh session per load: options set by a .geo file (Mesh.MeshSizeMax, ...) and
// onelab parameters (the `size` of DefineConstant) otherwise survive gmsh::clear() and
// leak into the next file. Gmsh 4.8 has no way to restore option defaults.
void freshGmsh() {
    static bool initialised = false;
    if (initialised) gmsh::finalize();
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 2);
    gmsh::logger::start();
    gmsh::onelab::clear();  // survives finalize()
    initialised = true;
}

std::string gmshErrors() {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    gmsh::logger::stop();
    gmsh::logger::start();
    std::string out;
    for (const auto& line : log)
        if (line.rfind("Error", 0) == 0) out += (out.empty() ? "" : "; ") + line;
    return out;
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw std::runtime_error("mesh '" + path + "': " + why);
}

std::string gmshTypeName(int type) {
    std::string name;
    int dim, order, numNodes, numPrimary;
    std::vector<double> coords;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, coords, numPrimary);
    return name;
}

// OpenCASCADE's volume (dim 3) or area (dim 2) of an entity; 0 where the entity is not
// OpenCASCADE's (the built-in kernel) or the query fails.
double occMeasure(int dim, int tag) {
    double m = 0.0;
    try {
        gmsh::model::occ::getMass(dim, tag, m);
    } catch (...) {
        m = 0.0;
    }
    return m;
}

// Volume and boundary area of the current model's 3-D entities: OpenCASCADE's exact values, or
// for entities of the built-in kernel those of their bounding boxes (an upper bound).
void geometryMeasures(double& volume, double& area) {
    volume = area = 0.0;
    gmsh::vectorpair vols;
    gmsh::model::getEntities(vols, 3);
    for (const auto& [dim, tag] : vols) {
        if (const double v = occMeasure(dim, tag); v > 0.0) {
            volume += v;
            continue;
        }
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
        volume += (x1 - x0) * (y1 - y0) * (z1 - z0);
    }
    gmsh::vectorpair faces;
    gmsh::model::getBoundary(vols, faces, false, false, false);
    for (const auto& [dim, tag] : faces) {
        if (const double a = occMeasure(2, std::abs(tag)); a > 0.0) {
            area += a;
            continue;
        }
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(2, std::abs(tag), x0, y0, z0, x1, y1, z1);
        const double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        area += std::max({dx * dy, dy * dz, dx * dz});
    }
    gmshErrors();  // a failed OpenCASCADE query leaves an error line that is not the file's
}

// Loads `path` into Gmsh's current model (meshing a .geo); caller holds the mutex.
void loadIntoGmsh(const std::string& path, const MeshOptions& opt) {
    if (!fs::exists(path)) fail(path, "file not found");
    if (fs::is_directory(path)) fail(path, "is a directory, expected a .msh or .geo file");
    const std::string ext = fs::path(path).extension().string();
    if (ext != ".msh" && ext != ".geo")
        fail(path, "unsupported extension '" + ext + "' (expected .msh or .geo)");
    if (opt.order < 0 || opt.order > 2)
        fail(path, "element order " + std::to_string(opt.order) + " not supported (1 or 2)");
    if (!(opt.size >= 0.0)) fail(path, "element size must be a positive number of metres");

    freshGmsh();
    if (ext == ".geo" && opt.size > 0.0) gmsh::onelab::setNumber("Parameters/size", {opt.size});
    try {
        gmsh::open(path);
    } catch (...) {
        fail(path, "Gmsh could not read it: " + gmshErrors());
    }
    if (std::string err = gmshErrors(); !err.empty()) fail(path, "Gmsh: " + err);

    if (ext == ".geo") {
        if (opt.size > 0.0) {
            double current = 0.0;
            gmsh::option::getNumber("Mesh.MeshSizeMax", current);
            gmsh::option::setNumber("Mesh.MeshSizeMax", std::min(current, opt.size));
        }
        if (opt.beforeMeshing) {
            double size = 0.0, factor = 1.0, volume = 0.0, area = 0.0;
            gmsh::option::getNumber("Mesh.MeshSizeMax", size);
            gmsh::option::getNumber("Mesh.MeshSizeFactor", factor);
            geometryMeasures(volume, area);
            MeshEstimate e = estimateMesh(volume, area, size * factor, opt.order == 0 ? 2 : opt.order);
            e.path = path;
            opt.beforeMeshing(e);
        }
        try {
            gmsh::model::mesh::generate(3);
        } catch (...) {
        }
        if (std::string err = gmshErrors(); !err.empty()) fail(path, "meshing failed: " + err);
        gmsh::model::mesh::setOrder(opt.order == 0 ? 2 : opt.order);
    } else if (opt.order != 0) {
        gmsh::model::mesh::setOrder(opt.order);
    }
    if (std::string err = gmshErrors(); !err.empty()) fail(path, "Gmsh: " + err);
}

// Element tags of one dimension (all entities or one entity), by type.
struct TypedElements {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
};
TypedElements elementsOf(int dim, int entity) {
    TypedElements te;
    gmsh::model::mesh::getElements(te.types, te.tags, te.nodes, dim, entity);
    return te;
}

namespace {

// The one volume element type of the mesh (Gmsh's 4: Tet4, 11: Tet10); fails naming the path.
int volumeElementType(const std::string& path, const TypedElements& vol) {
    int volType = -1;
    for (std::size_t k = 0; k < vol.types.size(); ++k) {
        if (vol.tags[k].empty()) continue;
        const int t = vol.types[k];
        if (t != 4 && t != 11)
            fail(path, "unsupported volume element type '" + gmshTypeName(t) + "' (" +
                           std::to_string(vol.tags[k].size()) +
                           " elements); flexehd supports 4-node and 10-node tetrahedra");
        if (volType != -1 && volType != t)
            fail(path, "mixes 4-node and 10-node tetrahedra; use one element order");
        volType = t;
    }
    if (volType == -1)
        fail(path, "no volume elements (tetrahedra); is the 3-D mesh generated and saved?");
    return volType;
}

// The nodes the volume elements use, numbered compactly into mesh.nodes and mesh.nodeTags;
// returns Gmsh node tag → index (−1: unused).
std::vector<Index> compactNodes(const std::string& path, const std::vector<std::size_t>& vnodes, Mesh& mesh) {
    std::vector<std::size_t> nodeTags;
    std::vector<double> coords, param;
    gmsh::model::mesh::getNodes(nodeTags, coords, param, -1, -1, false, false);
    std::size_t maxTag = 0;
    for (auto t : nodeTags) maxTag = std::max(maxTag, t);
    std::vector<Index> tagToIndex(maxTag + 1, -1);
    std::vector<std::size_t> tagToCoord(maxTag + 1, 0);
    for (std::size_t i = 0; i < nodeTags.size(); ++i) tagToCoord[nodeTags[i]] = i;
    std::vector<bool> known(maxTag + 1, false);
    for (auto t : nodeTags) known[t] = true;
    Index count = 0;
    for (auto t : vnodes) {
        if (t > maxTag || !known[t]) fail(path, "volume element refers to missing node " + std::to_string(t));
        if (tagToIndex[t] < 0) tagToIndex[t] = count++;
    }
    mesh.nodes.resize(3, count);
    mesh.nodeTags.resize(count);
    for (std::size_t t = 0; t <= maxTag; ++t) {
        if (tagToIndex[t] < 0) continue;
        const Index i = tagToIndex[t];
        const std::size_t c = tagToCoord[t];
        mesh.nodes.col(i) << coords[3 * c], coords[3 * c + 1], coords[3 * c + 2];
        mesh.nodeTags[i] = t;
    }
    return tagToIndex;
}

// The physical groups of dimension 2 and 3 (volume groups by element index; surface groups by
// triangle, the triangles of all surface groups collected once into mesh.surface).
void readPhysicalGroups(const std::string& path, const std::vector<Index>& tagToIndex,
                        const std::unordered_map<std::size_t, Index>& volIndex, Mesh& mesh) {
    const std::size_t maxTag = tagToIndex.size() - 1;
    const int triType = mesh.order() == 2 ? 9 : 2;
    mesh.surface.type = mesh.order() == 2 ? ElementType::Tri6 : ElementType::Tri3;
    const int npt = nodesPerElement(mesh.surface.type);
    std::unordered_map<std::size_t, Index> triIndex;
    std::vector<Index> triNodes;
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto& [dim, tag] : groups) {
        if (dim < 2) continue;
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        if (name.empty()) name = std::to_string(tag);
        if (mesh.groups.count(name))
            fail(path, "physical group name '" + name + "' is used twice");
        PhysicalGroup g{name, dim, {}};
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
        for (int ent : entities) {
            TypedElements te = elementsOf(dim, ent);
            for (std::size_t k = 0; k < te.types.size(); ++k) {
                if (dim == 3) {
                    for (auto t : te.tags[k]) g.elements.push_back(volIndex.at(t));
                    continue;
                }
                if (te.types[k] != triType)
                    fail(path, "physical surface '" + name + "' has unsupported elements '" +
                                   gmshTypeName(te.types[k]) + "'; expected " +
                                   std::string(fem::name(mesh.surface.type)) +
                                   " triangles matching the volume order");
                for (std::size_t i = 0; i < te.tags[k].size(); ++i) {
                    auto [it, inserted] = triIndex.try_emplace(te.tags[k][i], Index(triIndex.size()));
                    if (inserted) {
                        for (int a = 0; a < npt; ++a) {
                            const std::size_t nt = te.nodes[k][i * npt + a];
                            if (nt > maxTag || tagToIndex[nt] < 0)
                                fail(path, "triangle " + std::to_string(te.tags[k][i]) + " of '" +
                                               name + "' has a node not on any tetrahedron");
                            triNodes.push_back(tagToIndex[nt]);
                        }
                        mesh.surface.tags.push_back(te.tags[k][i]);
                    }
                    g.elements.push_back(it->second);
                }
            }
        }
        mesh.groups.emplace(name, std::move(g));
    }
    mesh.surface.nodes = Eigen::Map<Eigen::Matrix<Index, Eigen::Dynamic, Eigen::Dynamic>>(
        triNodes.data(), npt, static_cast<Index>(triNodes.size() / std::max(npt, 1)));
}

}  // namespace

Mesh extractMesh(const std::string& path) {
    Mesh mesh;
    mesh.source = path;
    // Volume elements: every 3-D entity.
    TypedElements vol = elementsOf(3, -1);
    const int volType = volumeElementType(path, vol);
    const std::size_t kv = std::find(vol.types.begin(), vol.types.end(), volType) - vol.types.begin();
    mesh.volume.type = volType == 4 ? ElementType::Tet4 : ElementType::Tet10;
    const int npe = nodesPerElement(mesh.volume.type);
    const auto& vnodes = vol.nodes[kv];
    const std::vector<Index> tagToIndex = compactNodes(path, vnodes, mesh);
    const Index ne = static_cast<Index>(vol.tags[kv].size());
    mesh.volume.nodes.resize(npe, ne);
    mesh.volume.tags = vol.tags[kv];
    for (Index e = 0; e < ne; ++e)
        for (int a = 0; a < npe; ++a) mesh.volume.nodes(a, e) = tagToIndex[vnodes[std::size_t(e) * npe + a]];
    std::unordered_map<std::size_t, Index> volIndex;
    volIndex.reserve(ne);
    for (Index e = 0; e < ne; ++e) volIndex[mesh.volume.tags[e]] = e;
    readPhysicalGroups(path, tagToIndex, volIndex, mesh);
    return mesh;
}

}  // namespace

MeshEstimate estimateMesh(double volume, double area, double size, int order) {
    // Fitted to Gmsh's counts for meshes/piston.geo and meshes/liner.geo at their documented sizes
    // and a 0.1 m cube at 0.01 to 0.0033 m (docs/meshes.md, "Estimate before meshing").
    constexpr double kV = 0.45, kA = 1.18, kF = 0.85;
    MeshEstimate e;
    e.size = size;
    e.order = order;
    e.volume = volume;
    e.area = area;
    if (!(size > 0.0)) return e;
    e.triangles = kA * area / (std::sqrt(3.0) / 4.0 * size * size);
    e.tetrahedra = kV * volume / (size * size * size / (6.0 * std::sqrt(2.0))) + kF * e.triangles;
    // Euler's relation: N₁ ≈ T/6 + F/4; edges E ≈ N₁ + T + F/2, one mid-node each at order 2.
    const double n1 = e.tetrahedra / 6.0 + e.triangles / 4.0;
    e.nodes = order == 1 ? n1 : 2.0 * n1 + e.tetrahedra + e.triangles / 2.0;
    return e;
}

double sizeForNodes(double volume, double area, double maxNodes, int order) {
    // nodes(size) falls as the size grows: bisect log(size) between 1 pm and 1 km.
    double lo = 1e-12, hi = 1e3;
    if (estimateMesh(volume, area, lo, order).nodes <= maxNodes) return lo;
    for (int i = 0; i < 200 && hi > lo * (1.0 + 1e-9); ++i) {
        const double mid = std::sqrt(lo * hi);
        (estimateMesh(volume, area, mid, order).nodes <= maxNodes ? hi : lo) = mid;
    }
    return hi;
}

Mesh readMesh(const std::string& path, const MeshOptions& options) {
    Mesh mesh;
    {
        std::lock_guard<std::mutex> lock(gmshMutex());
        loadIntoGmsh(path, options);
        mesh = extractMesh(path);
        gmsh::clear();
    }
    if (options.checkElements) mesh.checkElements();
    return mesh;
}

void convertMesh(const std::string& path, const std::string& out, double mshVersion,
                 const MeshOptions& options) {
    std::lock_guard<std::mutex> lock(gmshMutex());
    loadIntoGmsh(path, options);
    gmsh::option::setNumber("Mesh.MshFileVersion", mshVersion);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::write(out);
    if (std::string err = gmshErrors(); !err.empty()) fail(out, "writing failed: " + err);
    gmsh::clear();
}

}  // namespace flexehd::fem
