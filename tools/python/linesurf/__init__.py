"""linesurf: watertight piecewise-planar meshes from 3D line segments seen from known
viewpoints (Langlois, Boulch & Marlet, 3DV 2019), through the linesurf library's facade.

    import linesurf
    scene = linesurf.read_scene("lines.json")
    result = linesurf.reconstruct(scene, scene_mode="exterior", weights={"visibility": 0.5})
    linesurf.write_mesh("house.ply", result.mesh)

Arrays in: segments (n, 2, 3) or (n, 6) float, viewpoints (m, 3) float, observations (k, 2)
integer (segment index, viewpoint index). Options are keyword arguments named as the fields of
the C++ ReconstructOptions / DetectOptions; groups (detection, weights, solver, quality) take a dict.
Failures raise linesurf.Error subclasses (InvalidInput, InvalidOptions, Cancelled, ...); Ctrl-C
cancels a run and raises KeyboardInterrupt. docs/user/embedding.md has the whole guide.
"""

from . import _linesurf
from ._errors import (Cancelled, Degenerate, Error, Internal, InvalidInput, InvalidOptions,
                      ResourceExhausted, SolverFailed)
from ._linesurf import (DetectionParameters, DetectOptions, EnergyWeights, QualityOptions,
                        ReconstructOptions, SolverOptions)
from ._types import DetectResult, Mesh, ReconstructResult, Scene

__version__ = _linesurf.__version__

__all__ = [
    "Cancelled", "Degenerate", "DetectOptions", "DetectResult", "DetectionParameters",
    "EnergyWeights", "Error", "Internal", "InvalidInput", "InvalidOptions", "Mesh",
    "QualityOptions", "ReconstructOptions", "ReconstructResult", "Reconstruction", "ResourceExhausted", "Scene", "SolverFailed",
    "SolverOptions", "detect_planes", "read_scene", "reconstruct", "write_mesh",
]


def _set_options(target, options, prefix=""):
    """Sets the fields named by `options` on an options object; groups take dicts."""
    fields = type(target)._fields
    for name, value in options.items():
        path = prefix + name
        if name not in fields:
            raise TypeError(f"unknown option '{path}' (options here: {', '.join(fields)})")
        group = getattr(target, name)
        if isinstance(value, dict):
            if not hasattr(type(group), "_fields"):
                raise TypeError(f"option '{path}' takes a value, not a dict")
            _set_options(group, value, path + ".")
            continue
        try:
            setattr(target, name, value)
        except TypeError:
            raise TypeError(
                f"option '{path}' cannot be {value!r} ({type(value).__name__})") from None
        except ValueError as error:
            raise InvalidOptions(f"{prefix}{error}", code="invalid_options",
                                 stage="python") from None


def _options(options_type, options):
    result = options_type()
    _set_options(result, options)
    return result


def _scene_arrays(segments, viewpoints, observations):
    if isinstance(segments, Scene):
        if viewpoints is not None or observations is not None:
            raise TypeError("pass a Scene alone or segments, viewpoints and observations")
        return segments.segments, segments.viewpoints, segments.observations
    return segments, viewpoints, observations


def reconstruct(segments, viewpoints=None, observations=None, *, planes=None, memberships=None,
                progress=None, log=None, **options):
    """Reconstructs a watertight mesh (the whole method: planes, cell complex, LP labelling).

    segments: (n, 2, 3) or (n, 6) float array, or a Scene (then with its viewpoints and
        observations; its planes are used only when passed as planes=).
    viewpoints: (m, 3) camera centres. observations: (k, 2) (segment, viewpoint) indices.
    planes, memberships: given planes (p, 2, 3) or (p, 6) (point, unit normal) and (q, 2)
        (segment, plane); with planes, plane_source defaults to "given".
    progress: progress(stage: str, fraction: float); returning True cancels (Cancelled).
    log: log(level: str, stage: str, message: str).
    options: fields of ReconstructOptions, e.g. scene_mode="exterior", seed=1,
        weights={"visibility": 0.5}, detection={"epsilon": 0.05}, solver={"backend": "clp"}.
    Returns a ReconstructResult.
    """
    return _result(_linesurf.reconstruct(
        *_reconstruct_inputs(segments, viewpoints, observations, planes, memberships, options),
        progress, log))


class Reconstruction:
    """A reconstruction prepared once (sanitation, planes, cell complex, scene mode) and solved
    as often as wanted with other energy weights (the reference's line_based_recons_param):

        prepared = linesurf.Reconstruction(scene, scene_mode="exterior")
        for v in (0.1, 0.5, 1.0):
            result = prepared.solve(visibility=v)

    The arguments are those of reconstruct(); solve(**weights) takes fields of EnergyWeights
    (the others keep the prepared options' values) and gives exactly the mesh of reconstruct()
    with those weights.
    """

    def __init__(self, segments, viewpoints=None, observations=None, *, planes=None,
                 memberships=None, progress=None, log=None, **options):
        self._prepared = _linesurf.prepare(
            *_reconstruct_inputs(segments, viewpoints, observations, planes, memberships,
                                 options),
            progress, log)

    @property
    def options(self):
        """The ReconstructOptions given at preparation."""
        return self._prepared.options

    def solve(self, *, progress=None, log=None, **weights):
        """Solves with the prepared options' weights changed by `weights`; a ReconstructResult."""
        chosen = self._prepared.options.weights
        _set_options(chosen, weights, "weights.")
        return _result(self._prepared.solve(chosen, progress, log))


def _reconstruct_inputs(segments, viewpoints, observations, planes, memberships, options):
    """The scene arrays and options of the compiled reconstruct/prepare."""
    if planes is not None:
        options.setdefault("plane_source", "given")
    return ((*_scene_arrays(segments, viewpoints, observations), planes, memberships),
            _options(ReconstructOptions, options))


def _result(raw):
    raw["mesh"] = Mesh(**raw["mesh"])
    return ReconstructResult(**raw)


def detect_planes(segments, viewpoints=None, observations=None, *, progress=None, log=None,
                  **options):
    """Detects planes only (RANSAC with multiple support); options are fields of DetectOptions,
    e.g. detection={"epsilon": 0.05}, seed=1. Returns a DetectResult."""
    opts = _options(DetectOptions, options)
    arrays = (*_scene_arrays(segments, viewpoints, observations), None, None)
    raw = _linesurf.detect_planes(arrays, opts, progress, log)
    return DetectResult(**raw)


def read_scene(path, *, nvm=None, colmap=None, format="auto"):
    """Reads a scene file: reference JSON, Line3D++ .txt or LIMAP alltracks.txt (with nvm= or
    colmap=) or OBJ lines. format: "auto" (by extension and first line), "json", "line3dpp",
    "limap" or "obj". Returns a Scene."""
    return Scene(**_linesurf.read_scene(str(path), nvm or "", colmap or "", format))


def write_mesh(path, mesh, *, ascii=False, triangulate=False):
    """Writes a Mesh as PLY (binary unless ascii), OBJ or OFF by the extension, atomically;
    the bytes of `linesurf reconstruct -o`."""
    opts = _linesurf.MeshWriteOptions()
    opts.ascii = ascii
    opts.triangulate = triangulate
    _linesurf.write_mesh(str(path), mesh.vertices, mesh.face_offsets, mesh.face_indices, opts)
