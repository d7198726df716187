"""Reads the VTU files deal.II writes (binary, zlib-compressed, inline base64), with the standard
library only: the arrays of a piece by name, plus its points and cell types; and a .pvtu record's
pieces (one per MPI rank) as one."""
import base64
import os
import struct
import xml.etree.ElementTree as ElementTree
import zlib

_FORMATS = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B", "Int64": "q", "UInt32": "I"}


def _decode(array):
    text = "".join((array.text or "").split()) if array is not None else ""
    if not text:
        return []  # an empty piece (an MPI rank without cells of this output)
    # A header of four uint32 (blocks, block size, last block size, compressed size), base64 on
    # its own, then the compressed block.
    header_length = 4 * ((16 + 2) // 3)
    blocks, _, _, compressed = struct.unpack("<4I", base64.b64decode(text[:header_length]))
    if blocks != 1:
        raise ValueError(f"{blocks} compressed blocks; only one is supported")
    raw = zlib.decompress(base64.b64decode(text[header_length:])[:compressed])
    code = _FORMATS[array.get("type")]
    values = struct.unpack(f"<{len(raw) // struct.calcsize(code)}{code}", raw)
    components = int(array.get("NumberOfComponents", "1"))
    if components == 1:
        return list(values)
    return [values[i:i + components] for i in range(0, len(values), components)]


def read(path):
    """{'points': [(x, y, z)], 'types': [int], 'fields': {name: values}} of a .vtu file."""
    piece = ElementTree.parse(path).getroot().find("UnstructuredGrid/Piece")
    fields = {a.get("Name"): _decode(a) for a in piece.find("PointData")}
    return {
        "points": _decode(piece.find("Points/DataArray")),
        "types": _decode(piece.find("Cells/DataArray[@Name='types']")),
        "fields": fields,
    }


def read_record(path):
    """read() of every piece a .pvtu record lists, concatenated in its order (empty pieces, of
    ranks without cells of this output, add nothing)."""
    root = ElementTree.parse(path).getroot()
    whole = {"points": [], "types": [], "fields": {}}
    for source in root.iter("Piece"):
        piece = read(os.path.join(os.path.dirname(path), source.get("Source")))
        if not piece["points"]:
            continue
        whole["points"] += piece["points"]
        whole["types"] += piece["types"]
        for name, values in piece["fields"].items():
            whole["fields"].setdefault(name, []).extend(values)
    return whole


def pvd_frames(path):
    """[(time, file)] of a .pvd collection."""
    root = ElementTree.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]
