"""Result classes of the linesurf package: plain containers of numpy arrays."""

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Mesh:
    """A polygon mesh, faces counter-clockwise seen from outside.

    Face f uses ``face_indices[face_offsets[f]:face_offsets[f + 1]]`` (indices into
    ``vertices``, an (n, 3) float64 array).
    """

    vertices: np.ndarray
    face_offsets: np.ndarray
    face_indices: np.ndarray

    @property
    def num_faces(self):
        return max(len(self.face_offsets) - 1, 0)

    def faces(self):
        """The faces as a list of index arrays."""
        return np.split(self.face_indices, self.face_offsets[1:-1])

    def triangles(self):
        """The faces as an (f, 3) array; the mesh must be triangulated (triangulate=True)."""
        sizes = np.diff(self.face_offsets)
        if np.any(sizes != 3):
            raise ValueError("the mesh has non-triangle faces: reconstruct with triangulate=True")
        return self.face_indices.reshape(-1, 3)

    @classmethod
    def from_faces(cls, vertices, faces):
        """A mesh from (n, 3) vertices and a list (or (f, k) array) of vertex index lists."""
        sizes = [len(f) for f in faces]
        offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.uint32)
        indices = (np.concatenate([np.asarray(f) for f in faces]).astype(np.uint32)
                   if faces is not None and len(faces) else np.zeros(0, np.uint32))
        return cls(np.asarray(vertices, dtype=np.float64), offsets, indices)


@dataclass
class ReconstructResult:
    """Result of reconstruct().

    planes: (p, 2, 3) float64, planes[i, 0] a point, planes[i, 1] the unit normal.
    memberships: (q, 2) uint32 (input segment, plane), sorted by segment then plane.
    report: the run's numbers (stage times, counts, eps and its source, LP size, solver status,
        energies and lower bound, mesh checks, quality figures unless measure_quality=False).
    """

    mesh: Mesh
    planes: np.ndarray
    memberships: np.ndarray
    report: dict
    warnings: list = field(default_factory=list)


@dataclass
class DetectResult:
    """Result of detect_planes(): planes as in ReconstructResult, per plane its inlier count
    and inlier length, memberships into the input segments, the report and warnings."""

    planes: np.ndarray
    inlier_count: np.ndarray
    inlier_length: np.ndarray
    memberships: np.ndarray
    report: dict
    warnings: list = field(default_factory=list)


@dataclass
class Scene:
    """A scene as read by read_scene(): segments (n, 2, 3), viewpoints (m, 3), observations
    (k, 2) (segment, viewpoint), planes (p, 2, 3), memberships (q, 2), warnings."""

    segments: np.ndarray
    viewpoints: np.ndarray
    observations: np.ndarray
    planes: np.ndarray
    memberships: np.ndarray
    warnings: list = field(default_factory=list)
