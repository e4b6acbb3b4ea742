#pragma once
// An editable triangle mesh with undo: vertices (a position and a VertexData each), faces, the
// alive faces around each vertex (sorted by index) and a log of the edits. Vertices and faces are
// only ever appended, killed, moved or (a face) given another corner, so rolling the log back
// restores every array exactly: a stage can try an edit, measure it and take it back. Used by the
// valence optimisation (operations tried and undone) and the simplification (collapses, no undo).
#include "mesh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace fieldcvt {

//! VertexData for a mesh whose vertices carry nothing but their position.
struct NoVertexData {};

template <class VertexData = NoVertexData>
class EditableMesh {
public:
    EditableMesh() = default;
    //! The mesh of `positions` and `faces`, every vertex with `data`. The faces' indices must be
    //! in range (the caller checks them).
    EditableMesh(std::vector<Vec3> positions, std::vector<Face> faces, const VertexData& data = {})
        : positions_(std::move(positions)), faces_(std::move(faces))
    {
        const int n = static_cast<int>(positions_.size());
        data_.assign(n, data);
        vertexAlive_.assign(n, 1);
        faceAlive_.assign(faces_.size(), 1);
        std::vector<int> degree(n, 0);
        for (const Face& t : faces_)
            for (int v : t) ++degree[v];
        vertexFaces_.resize(n);
        for (int v = 0; v < n; ++v) vertexFaces_[v].reserve(degree[v]);
        for (int f = 0; f < faceCount(); ++f)
            for (int v : faces_[f]) vertexFaces_[v].push_back(f);
    }

    // --- reading ------------------------------------------------------------------------------
    int vertexCount() const { return static_cast<int>(positions_.size()); }
    //! Faces ever made, killed ones included (face indices run up to this).
    int faceCount() const { return static_cast<int>(faces_.size()); }
    const Vec3& position(int v) const { return positions_[v]; }
    const std::vector<Vec3>& positions() const { return positions_; }
    const VertexData& data(int v) const { return data_[v]; }
    const Face& face(int f) const { return faces_[f]; }
    bool faceAlive(int f) const { return faceAlive_[f] != 0; }
    bool vertexAlive(int v) const { return vertexAlive_[v] != 0; }
    //! The alive faces around v, sorted by index.
    const std::vector<int>& facesOf(int v) const { return vertexFaces_[v]; }
    //! The faces containing both a and b.
    void edgeFaces(int a, int b, std::vector<int>& out) const
    {
        out.clear();
        for (int f : vertexFaces_[a])
            if (hasCorner(f, b)) out.push_back(f);
    }
    bool hasEdge(int a, int b) const
    {
        for (int f : vertexFaces_[a])
            if (hasCorner(f, b)) return true;
        return false;
    }
    bool hasCorner(int f, int v) const
    {
        const Face& t = faces_[f];
        return t[0] == v || t[1] == v || t[2] == v;
    }

    // --- editing (logged while a log is open) -------------------------------------------------
    int addVertex(const Vec3& p, const VertexData& d)
    {
        const int v = vertexCount();
        positions_.push_back(p);
        data_.push_back(d);
        vertexAlive_.push_back(1);
        vertexFaces_.emplace_back();
        log(Kind::AddVertex, v);
        return v;
    }
    //! Marks v dead (its faces must be gone or going); its index stays.
    void killVertex(int v)
    {
        vertexAlive_[v] = 0;
        log(Kind::KillVertex, v);
    }
    //! Moves v to p with new data. Without an open log, safe in parallel for distinct vertices.
    void setVertex(int v, const Vec3& p, const VertexData& d)
    {
        if (logging_) {
            undo_.push_back({Kind::SetVertex, v, 0, 0});
            saved_.push_back({positions_[v], data_[v]});
        }
        positions_[v] = p;
        data_[v] = d;
    }
    void setData(int v, const VertexData& d) { setVertex(v, positions_[v], d); }
    int addFace(const Face& t)
    {
        const int f = faceCount();
        faces_.push_back(t);
        faceAlive_.push_back(1);
        for (int v : t) vertexFaces_[v].push_back(f);  // the largest index: stays sorted
        log(Kind::AddFace, f);
        return f;
    }
    void killFace(int f)
    {
        faceAlive_[f] = 0;
        for (int v : faces_[f]) erase(vertexFaces_[v], f);
        log(Kind::KillFace, f);
    }
    //! Face f's corner `from` becomes `to` (its index and orientation stay).
    void renameCorner(int f, int from, int to)
    {
        Face& t = faces_[f];
        const int k = t[0] == from ? 0 : t[1] == from ? 1 : 2;
        t[k] = to;
        erase(vertexFaces_[from], f);
        insert(vertexFaces_[to], f);
        if (logging_) undo_.push_back({Kind::RenameCorner, f, k, from});
    }

    // --- undo ---------------------------------------------------------------------------------
    //! Where an edit starts: the log's length then, and whether a log was open already.
    struct Mark {
        std::size_t logSize;
        bool wasLogging;
    };
    //! Opens the log (or continues an open one) and marks where the edit starts.
    Mark begin()
    {
        const Mark mark{undo_.size(), logging_};
        logging_ = true;
        return mark;
    }
    //! Takes back every edit since `mark`; the log is open again only if it was before.
    void rollback(const Mark& mark)
    {
        while (undo_.size() > mark.logSize) {
            undo(undo_.back());
            undo_.pop_back();
        }
        logging_ = mark.wasLogging;
    }
    //! Keeps the edits since `mark`; an outermost edit empties the log (nothing left to undo).
    void commit(const Mark& mark)
    {
        logging_ = mark.wasLogging;
        if (!logging_) undo_.clear(), saved_.clear();
    }
    bool logging() const { return logging_; }

private:
    enum class Kind : std::uint8_t { AddVertex, KillVertex, SetVertex, AddFace, KillFace, RenameCorner };
    struct Entry {
        Kind kind;
        int index;
        int corner;  //!< RenameCorner: which corner of the face
        int from;    //!< RenameCorner: the vertex it had
    };
    //! A vertex as it was before a SetVertex entry (one per such entry, in the same order).
    struct Saved {
        Vec3 position;
        VertexData data;
    };

    void log(Kind kind, int index)
    {
        if (logging_) undo_.push_back({kind, index, 0, 0});
    }
    static void erase(std::vector<int>& list, int f) { list.erase(std::lower_bound(list.begin(), list.end(), f)); }
    static void insert(std::vector<int>& list, int f) { list.insert(std::lower_bound(list.begin(), list.end(), f), f); }

    void undo(const Entry& e)
    {
        switch (e.kind) {
        case Kind::AddVertex:
            positions_.pop_back();
            data_.pop_back();
            vertexAlive_.pop_back();
            vertexFaces_.pop_back();
            break;
        case Kind::KillVertex: vertexAlive_[e.index] = 1; break;
        case Kind::SetVertex:
            positions_[e.index] = saved_.back().position;
            data_[e.index] = saved_.back().data;
            saved_.pop_back();
            break;
        case Kind::AddFace:
            for (int v : faces_[e.index]) vertexFaces_[v].pop_back();  // it was appended last
            faces_.pop_back();
            faceAlive_.pop_back();
            break;
        case Kind::KillFace:
            faceAlive_[e.index] = 1;
            for (int v : faces_[e.index]) insert(vertexFaces_[v], e.index);
            break;
        case Kind::RenameCorner: {
            int& corner = faces_[e.index][e.corner];
            erase(vertexFaces_[corner], e.index);
            insert(vertexFaces_[e.from], e.index);
            corner = e.from;
            break;
        }
        }
    }

    std::vector<Vec3> positions_;
    std::vector<VertexData> data_;
    std::vector<char> vertexAlive_;
    std::vector<Face> faces_;
    std::vector<char> faceAlive_;
    std::vector<std::vector<int>> vertexFaces_;  //!< alive incident faces, sorted
    std::vector<Entry> undo_;
    std::vector<Saved> saved_;
    bool logging_ = false;
};

}  // namespace fieldcvt
