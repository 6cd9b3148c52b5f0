"""The DXF renderer: the only module that imports ezdxf.

A sheet becomes a DXF R2010 drawing in millimetres ($INSUNITS 4, $MEASUREMENT
1), drawn in model space at 1:1 with the page's corner at the origin (DXF has
y up like the drawing interface, so nothing is flipped). $LIMMIN/$LIMMAX are
the page, $EXTMIN/$EXTMAX what was drawn (the page when nothing was).

Layers (GOST 2.303 line types), every entity BYLAYER:

    MAIN     continuous, the main line's weight (0.7 mm -> lineweight 70)
    THIN     continuous, thin (0.35 -> 35)
    DASHED   linetype GOST_DASHED from the look's dash pattern (dash 5, gap 1.5)
    DASHDOT  linetype GOST_DASHDOT (dash 15, gap, dot, gap: a DXF dot is a
             0-length element; the look's dot length goes to the gaps beside
             it, so the period stays the look's)
    TEXT     lettering: a TEXT per plain text, an MTEXT per label with
             indices (`rich_text`: "V_{BA}" is one MTEXT whose index is a
             stack, \\S^BA;, so the index follows its letter in any font)
    FILL     fill "black": solid HATCHes BYLAYER (colour 7, arrowheads);
             fill "white": a WIPEOUT (a circle as a 64-gon), DXF's own mask,
             drawn after what lies under it and before its own outline, so
             that it hides what is under it (a pin over links). A wipeout is
             the background colour in every output, monochrome too (a white
             HATCH prints black there); a program that does not draw
             wipeouts (LibreCAD 2.2) shows the lines under the pin instead.
             The wipeouts' frames are off ($WIPEOUTFRAME 0).

Lineweights are the nearest valid DXF lineweights to the look's widths.

Text style TEXT_STYLE, "OpenGostTypeA-Regular": LibreCAD and QCAD pick a
text's font by its style's name, and ship OpenGost Type A (GOST 2.304 type
A, with Cyrillic and Greek) under this name; the style's font file is
DejaVuSans.ttf, with Cyrillic and Greek and present on nearly every system,
for the programs that read TrueType files (the look's osifont is in no CAD
program's fonts: LibreCAD showed every Cyrillic and Greek letter as a
diamond). Oblique = the look's slant. A text's height is the lettering size (capital height, mm),
its width factor the look's squeeze for max_width, its alignment point `pos`
(DXF places oblique text by its baseline; the SVG renderer's shift that keeps
slanted capitals inside a cell is not applied). Content is written safely:
control characters become spaces or are dropped, a caret is written "^ " and
"%%" sequences are escaped, so that no content can change the file's
structure or turn into a DXF control code.

Groups: every entity drawn inside begin_group/end_group goes into a DXF GROUP
named after the group's id (made unique, case-insensitively as DXF compares
group names, and of letters, digits, "_", "-" and "$" only); the group's class
is its description. With nested groups an entity belongs to EVERY open group,
as RecordingBackend.in_group counts it. A group in which nothing was drawn is
not written (DXF audits remove empty groups).

Output is byte-reproducible: handles are counted by the document in drawing
order, and every date and GUID that ezdxf would take from the clock or a
random generator ($TDCREATE, $TDUCREATE, $TDUPDATE, $TDUUPDATE, $TDINDWG,
$TDUSRTIMER, $FINGERPRINTGUID, $VERSIONGUID, ezdxf's own CREATED_BY/WRITTEN_BY
marks) is fixed, to $SOURCE_DATE_EPOCH when that is set, else 2000-01-01 UTC.
The GUIDs are name-based (uuid5): the fingerprint one constant, the version
one from that date. ezdxf sets the clock's values in Drawing._update_metadata,
the last step of Drawing.write (ezdxf 1.1 to 1.4), so that step is wrapped for
the one write; to_bytes() raises if the stamp did not take. The CLASSES that
ezdxf adds from a set (whose order follows the hash seed) are registered in
sorted order first. Coordinates are written at full float precision.
"""

from __future__ import annotations

import io
import math
import os
import re
import unicodedata
import uuid
from collections import Counter
from collections.abc import Sequence
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import ezdxf
from ezdxf.document import CREATED_BY_EZDXF, WRITTEN_BY_EZDXF, Drawing
from ezdxf.enums import TextEntityAlignment
from ezdxf.lldxf.const import VALID_DXF_LINEWEIGHTS
from ezdxf.tools.juliandate import juliandate

from .backend import (
    LINE_TYPES,
    Backend,
    Fill,
    HAlign,
    LineType,
    PointLike,
    TextRun,
    VAlign,
    as_point,
    parse_markup,
)
from .look import Look

__all__ = [
    "DxfBackend",
    "LAYERS",
    "TEXT_LAYER",
    "FILL_LAYER",
    "TEXT_STYLE",
    "TEXT_FONT",
    "linetype_name",
    "mtext_content",
]

#: Layer of each line type.
LAYERS: dict[str, str] = {kind: kind.upper() for kind in LINE_TYPES}
TEXT_LAYER = "TEXT"
FILL_LAYER = "FILL"
TEXT_STYLE = "OpenGostTypeA-Regular"  # the name LibreCAD and QCAD resolve to their GOST font
TEXT_FONT = "DejaVuSans.ttf"  # for programs that read the style's TrueType file

# A dash of the look this short or shorter (other than the first) is a dot.
_DOT_MAX = 1.0
_INK_ACI = 7  # black on paper, white on a dark CAD screen
_DEFAULT_DATE = datetime(2000, 1, 1, tzinfo=UTC)
_GUID_NAMESPACE = uuid.uuid5(uuid.NAMESPACE_URL, "mmt_plans/render/dxf")

_ALIGNMENT = {
    ("left", "baseline"): TextEntityAlignment.LEFT,
    ("center", "baseline"): TextEntityAlignment.CENTER,
    ("right", "baseline"): TextEntityAlignment.RIGHT,
    ("left", "middle"): TextEntityAlignment.MIDDLE_LEFT,
    ("center", "middle"): TextEntityAlignment.MIDDLE_CENTER,
    ("right", "middle"): TextEntityAlignment.MIDDLE_RIGHT,
    ("left", "top"): TextEntityAlignment.TOP_LEFT,
    ("center", "top"): TextEntityAlignment.TOP_CENTER,
    ("right", "top"): TextEntityAlignment.TOP_RIGHT,
}

_NAME_BAD = re.compile(r"[^A-Za-z0-9_$-]+")
_NAME_MAX = 200  # DXF names may have 255 characters; room for a "-n"
# Characters that end a line somewhere (str.splitlines) become spaces; the
# other control, surrogate and unassigned-private characters are dropped.
_LINE_ENDS = frozenset("\t\n\v\f\r\x1c\x1d\x1e\x85\u2028\u2029")


def linetype_name(kind: str) -> str:
    """The DXF linetype of a line type: CONTINUOUS or GOST_<KIND> when dashed."""
    return "GOST_" + kind.upper()


def nearest_lineweight(width_mm: float) -> int:
    """The valid DXF lineweight (1/100 mm) nearest to `width_mm`."""
    wanted = width_mm * 100.0
    return min(VALID_DXF_LINEWEIGHTS, key=lambda lw: (abs(lw - wanted), lw))


def dxf_pattern(dash: Sequence[float]) -> list[float]:
    """An ezdxf simple linetype pattern [total, dash, -gap, 0 (dot), ...] from
    the look's (dash, gap, dash, gap, ...); a short dash other than the first
    becomes a dot whose length is shared by the gaps beside it."""
    elems = [float(d) for d in dash]
    if len(elems) % 2:
        elems = elems + elems  # SVG repeats an odd list to make it even
    out: list[float] = []
    for i, d in enumerate(elems):
        if i % 2 == 0:
            if i > 0 and d <= _DOT_MAX:
                out[-1] -= d / 2.0  # the gap before grows (gaps are negative)
                out.append(0.0)
                elems[i + 1] += d / 2.0  # and the gap after
            else:
                out.append(d)
        else:
            out.append(-d)
    return [sum(abs(e) for e in out)] + out


def clean_text(text: str) -> str:
    """One line of text with nothing that could break a DXF file."""
    out = []
    for ch in str(text):
        if ch in _LINE_ENDS:
            out.append(" ")
        elif unicodedata.category(ch) in ("Cc", "Cs"):
            continue
        else:
            out.append(ch)
    return "".join(out)


def encode_text(text: str) -> str:
    """TEXT content: cleaned, "^" as "^ " (DXF caret notation) and, where "%%"
    occurs, every "%" as "%%%" so that no %%d/%%c/%%u code is formed."""
    text = clean_text(text).replace("^", "^ ")
    if "%%" in text:
        text = text.replace("%", "%%%")
    return text


# MTEXT attachment points: top 1-3, middle 4-6, bottom 7-9; left, centre, right.
_ATTACH_ROW = {"top": 0, "middle": 3, "baseline": 3}
_ATTACH_COL = {"left": 1, "center": 2, "right": 3}
_STACK_BAD = frozenset("^/#;\\{}")
_WIPEOUT_SIDES = 64


def _mtext_escaped(text: str) -> str:
    """Plain MTEXT content: backslash and braces escaped, caret and %% as in TEXT."""
    return encode_text(text).replace("\\", "\\\\").replace("{", "\\{").replace("}", "\\}")


def mtext_content(runs: Sequence[TextRun]) -> str:
    """One MTEXT's content for a label's runs: an index as a stack with one
    line empty (\\S^BA; a subscript, \\S2^; a superscript), which AutoCAD,
    LibreCAD and ezdxf draw small beside the letter before it."""
    out = []
    for text, kind in runs:
        body = clean_text(text)
        if kind == "normal" or not body.strip() or _STACK_BAD & set(body):
            out.append(_mtext_escaped(body))
        elif kind == "sub":
            out.append(f"\\S^{encode_text(body)};")
        else:
            out.append(f"\\S{encode_text(body)}^;")
    return "".join(out)


def source_date() -> datetime:
    """$SOURCE_DATE_EPOCH as a UTC date, else 2000-01-01; a SettingError for a
    value that is not whole seconds (files.source_date_epoch, as the PDF)."""
    from ..files import source_date_epoch

    return source_date_epoch() or _DEFAULT_DATE


class _Bounds:
    """Extents of what was drawn."""

    def __init__(self) -> None:
        self.xmin = self.ymin = math.inf
        self.xmax = self.ymax = -math.inf

    def add(self, x: float, y: float) -> None:
        self.xmin, self.xmax = min(self.xmin, x), max(self.xmax, x)
        self.ymin, self.ymax = min(self.ymin, y), max(self.ymax, y)

    @property
    def empty(self) -> bool:
        return self.xmin > self.xmax


class DxfBackend(Backend):
    """Draws into an ezdxf document; `to_bytes()` / `save()` give the DXF."""

    sets_labels_whole = True  # a recorded label is replayed as one rich_text (MTEXT)

    def __init__(
        self,
        width: float = 841.0,
        height: float = 594.0,
        look: Look | None = None,
        *,
        title: str | None = None,
    ) -> None:
        super().__init__(width, height, look)
        self._taken: set[str] = set()  # group names in use, upper-case
        self._next_number: Counter[str] = Counter()
        # One entry per open group: its DXF name, description and entities.
        self._stack: list[tuple[str, str, list[Any]]] = []
        self._bounds = _Bounds()
        doc = ezdxf.new("R2010", setup=False, units=4)  # 4: millimetres
        doc.header["$MEASUREMENT"] = 1
        doc.header["$LTSCALE"] = 1.0
        doc.header["$CELTSCALE"] = 1.0
        doc.header["$LWDISPLAY"] = 1
        self._doc: Drawing = doc
        self._msp = doc.modelspace()
        self._msp.dxf.limmin = (0.0, 0.0)
        self._msp.dxf.limmax = (self.width, self.height)
        doc.set_modelspace_vport(self.height, center=(self.width / 2.0, self.height / 2.0))
        if title:
            doc.header.custom_vars.append("Title", clean_text(title))
        self._setup_tables()

    def _setup_tables(self) -> None:
        doc = self._doc
        for kind in LINE_TYPES:
            style = self.look.line(kind)
            linetype = "Continuous"
            if style.dash:
                linetype = linetype_name(kind)
                pattern = dxf_pattern(style.dash)
                period = "".join("." if e == 0 else ("__" if e > 0 else " ") for e in pattern[1:])
                shown = (period * 3).strip()
                doc.linetypes.add(linetype, pattern, description=f"GOST 2.303 {kind} {shown}")
            doc.layers.add(
                LAYERS[kind],
                color=_INK_ACI,
                linetype=linetype,
                lineweight=nearest_lineweight(style.width),
            )
        thin = nearest_lineweight(self.look.line("thin").width)
        doc.layers.add(TEXT_LAYER, color=_INK_ACI, lineweight=thin)
        doc.layers.add(FILL_LAYER, color=_INK_ACI, lineweight=0)
        doc.set_wipeout_variables(frame=0)
        lettering = self.look.lettering
        text_style: Any = doc.styles.add(TEXT_STYLE, font=TEXT_FONT)
        text_style.dxf.oblique = lettering.slant_deg
        text_style.dxf.height = 0.0  # the height is given by each text
        text_style.set_extended_font_data("DejaVu Sans")

    # --- output --------------------------------------------------------------

    def to_bytes(self) -> bytes:
        """The DXF file (UTF-8), the same bytes for the same drawing."""
        self.close()
        b = self._bounds
        if b.empty:
            extmin, extmax = (0.0, 0.0, 0.0), (self.width, self.height, 0.0)
        else:
            extmin, extmax = (b.xmin, b.ymin, 0.0), (b.xmax, b.ymax, 0.0)
        self._msp.dxf.extmin = extmin
        self._msp.dxf.extmax = extmax
        stream = io.StringIO()
        doc = self._doc
        when = source_date()
        update_metadata = doc._update_metadata

        def update_metadata_reproducibly() -> None:
            # Drawing.write() refreshes the header from the clock and a random
            # GUID in this last step before writing (ezdxf 1.1 to 1.4): the
            # clock's values are replaced before anything is written.
            update_metadata()
            _stamp(doc, when)
            # Set here too: ezdxf skips extents whose corner is the origin.
            doc.header["$EXTMIN"] = extmin
            doc.header["$EXTMAX"] = extmax

        # ezdxf registers a CLASS for each type in use from a set, whose order
        # depends on the hash seed: registered first here, sorted.
        for dxftype in sorted(doc.entitydb.dxf_types_in_use()):
            doc.classes.add_class(dxftype)
        doc._update_metadata = update_metadata_reproducibly  # type: ignore[method-assign]
        try:
            doc.write(stream)
        finally:
            del doc._update_metadata  # back to the class's method
        if doc.header["$VERSIONGUID"] != _version_guid(when):
            raise RuntimeError(
                "this ezdxf writes its header differently: the DXF is not reproducible"
            )
        return doc.encode(stream.getvalue())

    def save(self, path: str | os.PathLike[str]) -> Path:
        path = Path(path)
        path.write_bytes(self.to_bytes())
        return path

    # --- helpers -------------------------------------------------------------

    def _add(self, entity: Any) -> None:
        for _name, _desc, members in self._stack:
            members.append(entity)

    def _attribs(self, line: LineType) -> dict[str, Any]:
        return {"layer": LAYERS[line]}

    def _points(self, points: Sequence[PointLike]) -> list[tuple[float, float]]:
        pts = [as_point(p) for p in points]
        if not pts:
            raise ValueError("a polyline needs at least one point")
        for x, y in pts:
            self._bounds.add(x, y)
        return pts

    def _black(self) -> Any:
        hatch = self._msp.add_hatch(dxfattribs={"layer": FILL_LAYER})
        hatch.set_solid_fill(color=256)  # BYLAYER
        return hatch

    def _mask(self, points: Sequence[tuple[float, float]]) -> None:
        """A white fill: a WIPEOUT over `points` (never a white HATCH, which
        monochrome output prints black)."""
        wipeout = self._msp.add_wipeout(points)
        wipeout.dxf.layer = FILL_LAYER  # add_wipeout does not take its dxfattribs (ezdxf 1.4)
        self._add(wipeout)

    # --- the interface -------------------------------------------------------

    def line(self, start: PointLike, end: PointLike, line: LineType = "main") -> None:
        self._check_line(line)
        s, e = self._points([start, end])
        self._add(self._msp.add_line(s, e, dxfattribs=self._attribs(line)))

    def polyline(self, points: Sequence[PointLike], line: LineType = "main") -> None:
        self._check_line(line)
        pts = self._points(points)
        if len(pts) < 2:
            return  # a single point draws nothing, as in SVG
        self._add(self._msp.add_lwpolyline(pts, format="xy", dxfattribs=self._attribs(line)))

    def polygon(
        self, points: Sequence[PointLike], line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        pts = self._points(points)
        if fill == "white" and _area(pts) != 0.0:
            self._mask(pts)
        elif fill == "black" and _area(pts) != 0.0:
            hatch = self._black()
            hatch.paths.add_polyline_path(pts, is_closed=True)
            self._add(hatch)
        if line is not None and len(pts) >= 2:
            self._add(
                self._msp.add_lwpolyline(
                    pts, format="xy", close=True, dxfattribs=self._attribs(line)
                )
            )

    def circle(
        self, center: PointLike, radius: float, line: LineType | None = "main", fill: Fill = "none"
    ) -> None:
        self._check_line(line, allow_none=True)
        self._check_fill(fill)
        if not radius > 0:
            raise ValueError(f"circle radius must be positive, got {radius}")
        cx, cy = as_point(center)
        r = float(radius)
        self._bounds.add(cx - r, cy - r)
        self._bounds.add(cx + r, cy + r)
        if fill == "white":
            self._mask(
                [
                    (
                        cx + r * math.cos(2.0 * math.pi * i / _WIPEOUT_SIDES),
                        cy + r * math.sin(2.0 * math.pi * i / _WIPEOUT_SIDES),
                    )
                    for i in range(_WIPEOUT_SIDES)
                ]
            )
        elif fill == "black":
            hatch = self._black()
            hatch.paths.add_edge_path().add_arc((cx, cy), r, 0.0, 360.0)
            self._add(hatch)
        if line is not None:
            self._add(self._msp.add_circle((cx, cy), r, dxfattribs=self._attribs(line)))

    def arc(
        self,
        center: PointLike,
        radius: float,
        start_deg: float,
        end_deg: float,
        line: LineType = "main",
    ) -> None:
        self._check_line(line)
        if not radius > 0:
            raise ValueError(f"arc radius must be positive, got {radius}")
        span = (end_deg - start_deg) % 360.0
        if span == 0.0:
            if end_deg == start_deg:
                return
            span = 360.0
        cx, cy = as_point(center)
        if span >= 360.0:
            self.circle((cx, cy), radius, line)
            return
        r = float(radius)
        start = float(start_deg) % 360.0
        end = (start + span) % 360.0
        # Extents: the ends and every axis direction the arc passes.
        for deg in [start, start + span] + [
            q for q in range(0, 720, 90) if start < q < start + span
        ]:
            a = math.radians(deg)
            self._bounds.add(cx + r * math.cos(a), cy + r * math.sin(a))
        self._add(self._msp.add_arc((cx, cy), r, start, end, dxfattribs=self._attribs(line)))

    def text(
        self,
        pos: PointLike,
        content: str,
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
        max_width: float | None = None,
    ) -> None:
        self._check_text(size, anchor, valign, max_width)
        content = str(content)
        x, y = as_point(pos)
        lettering = self.look.lettering
        squeeze = lettering.squeeze(content, size, max_width)
        rotation = float(rotation) % 360.0
        body = encode_text(content)
        entity = self._msp.add_text(
            body,
            height=float(size),
            rotation=rotation,
            dxfattribs={
                "layer": TEXT_LAYER,
                "style": TEXT_STYLE,
                "oblique": lettering.slant_deg,
                "width": squeeze,
            },
        )
        entity.set_placement((x, y), align=_ALIGNMENT[(anchor, valign)])
        self._add(entity)
        # Extents: the capitals' box estimated from the look's metrics.
        w = lettering.width(content, size, max_width)
        x0 = {"left": 0.0, "center": -w / 2.0, "right": -w}[anchor]
        y0 = {"baseline": 0.0, "middle": -size / 2.0, "top": -size}[valign]
        a = math.radians(rotation)
        ca, sa = math.cos(a), math.sin(a)
        for u, v in ((x0, y0), (x0 + w, y0), (x0, y0 + size), (x0 + w, y0 + size)):
            self._bounds.add(x + u * ca - v * sa, y + u * sa + v * ca)

    def rich_text(
        self,
        pos: PointLike,
        content: str | Sequence[TextRun],
        size: float = 3.5,
        *,
        anchor: HAlign = "left",
        valign: VAlign = "baseline",
        rotation: float = 0.0,
    ) -> float:
        """A label with indices as ONE MTEXT (`mtext_content`): separate
        texts placed by osifont's widths collide under any other font."""
        runs = parse_markup(content) if isinstance(content, str) else list(content)
        self._check_text(size, anchor, valign)
        let = self.look.lettering
        small = let.index_size(size)
        widths = [let.advance_width(t, size if k == "normal" else small) for t, k in runs]
        total = sum(widths) + (math.tan(math.radians(let.slant_deg)) * size if runs else 0.0)
        body = mtext_content(runs)
        if not body.strip():
            return total
        x, y = as_point(pos)
        rotation = float(rotation) % 360.0
        a = math.radians(rotation)
        ca, sa = math.cos(a), math.sin(a)
        # MTEXT has no baseline attachment: a baseline text hangs by the
        # middle of its capitals, half a height above the baseline.
        lift = size / 2.0 if valign == "baseline" else 0.0
        at = (x - lift * sa, y + lift * ca)
        mtext = self._msp.add_mtext(
            body,
            dxfattribs={"layer": TEXT_LAYER, "style": TEXT_STYLE, "char_height": float(size)},
        )
        mtext.set_location(
            at, rotation=rotation, attachment_point=_ATTACH_ROW[valign] + _ATTACH_COL[anchor]
        )
        self._add(mtext)
        x0 = {"left": 0.0, "center": -total / 2.0, "right": -total}[anchor]
        top = {"baseline": size, "middle": size / 2.0, "top": 0.0}[valign]
        bottom = top - 1.3 * size  # a subscript drops 0.3 h below the baseline
        for u, v in ((x0, bottom), (x0 + total, bottom), (x0, top), (x0 + total, top)):
            self._bounds.add(x + u * ca - v * sa, y + u * sa + v * ca)
        return total

    def _begin_group(self, id: str, cls: str | None) -> None:
        self._stack.append((self._unique_name(id), cls or "", []))

    def _end_group(self) -> None:
        name, description, members = self._stack.pop()
        if members:
            group = self._doc.groups.new(name, description=clean_text(description))
            group.set_data(members)
            # Each member points back at its groups (ezdxf before 1.2 left it to audit).
            handle = group.dxf.handle
            for entity in members:
                if handle not in entity.get_reactors():
                    entity.append_reactor_handle(handle)

    def _unique_name(self, wanted: str) -> str:
        """A DXF group name from `wanted`, unique (case-insensitively, as DXF
        compares group names) in this document: "plan", "plan-2", "plan-3"."""
        base = _NAME_BAD.sub("-", clean_text(wanted)).strip("-")[:_NAME_MAX] or "G"
        key = base.upper()
        n = self._next_number[key]
        name = base if n <= 1 else f"{base}-{n}"
        while name.upper() in self._taken:
            n += 1
            name = f"{base}-{n}"
        self._next_number[key] = n + 1
        self._taken.add(name.upper())
        return name


def _area(points: Sequence[tuple[float, float]]) -> float:
    """Twice the signed area of a polygon (shoelace)."""
    return sum(
        x0 * y1 - x1 * y0
        for (x0, y0), (x1, y1) in zip(points, [*points[1:], *points[:1]], strict=True)
    )


def _stamp(doc: Drawing, when: datetime) -> None:
    """Replace what ezdxf takes from the clock and the random generator."""
    date = juliandate(when.astimezone(UTC).replace(tzinfo=None))
    for var in ("$TDCREATE", "$TDUCREATE", "$TDUPDATE", "$TDUUPDATE"):
        doc.header[var] = date
    doc.header["$TDINDWG"] = 0.0
    doc.header["$TDUSRTIMER"] = 0.0
    doc.header["$FINGERPRINTGUID"] = _guid("fingerprint")
    doc.header["$VERSIONGUID"] = _version_guid(when)
    marker = f"{ezdxf.__version__} @ {when.isoformat()}"
    meta = doc.ezdxf_metadata()
    meta[CREATED_BY_EZDXF] = marker
    meta[WRITTEN_BY_EZDXF] = marker


def _version_guid(when: datetime) -> str:
    return _guid("version " + when.isoformat())


def _guid(what: str) -> str:
    return "{" + str(uuid.uuid5(_GUID_NAMESPACE, what)).upper() + "}"
