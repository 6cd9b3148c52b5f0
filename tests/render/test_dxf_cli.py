"""`mmt-plans draw FILE --format dxf` and `batch --format dxf`: both sheets as
DXF that ezdxf reads back and audits clean, in millimetres, A1, with text."""

from __future__ import annotations

from pathlib import Path

import ezdxf
from click.testing import CliRunner

from mmt_plans.cli import main

ROOT = Path(__file__).resolve().parents[2]


def _audited(path: Path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors and not auditor.has_fixes, auditor.errors
    return doc


def test_draw_writes_both_sheets_as_dxf(tmp_path):
    result = CliRunner().invoke(main, ["draw", str(ROOT / "samples" / "six_link_press.toml"),
                                       "--format", "dxf", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    for n in (1, 2):
        doc = _audited(tmp_path / f"sheet{n}.dxf")
        assert doc.header["$INSUNITS"] == 4  # millimetres
        lo, hi = doc.header["$LIMMIN"], doc.header["$LIMMAX"]
        assert (tuple(lo)[:2], tuple(hi)[:2]) == ((0.0, 0.0), (841.0, 594.0))
        msp = doc.modelspace()
        texts = [e.dxf.text for e in msp.query("TEXT")] + [e.text for e in msp.query("MTEXT")]
        assert len(texts) > 50 and any("μ" in t for t in texts)
        layers = {e.dxf.layer for e in msp}
        assert {"MAIN", "THIN", "TEXT"} <= layers
        # issue 24: the guides' centre lines are on DASHDOT, whose linetype has
        # a real dash-dot pattern (dash, gap, dot, gap)
        assert msp.query('LINE[layer=="DASHDOT"]')
        pattern = doc.linetypes.get(doc.layers.get("DASHDOT").dxf.linetype).pattern_tags.tags
        elements = [t.value for t in pattern if t.code == 49]
        assert len(elements) == 4 and elements[0] > 0 and elements[2] == 0
        for e in msp.query("LINE"):
            for p in (e.dxf.start, e.dxf.end):
                assert 0.0 <= p.x <= 841.0 and 0.0 <= p.y <= 594.0


def test_batch_writes_dxf_sheets(tmp_path):
    result = CliRunner().invoke(main, ["batch", str(ROOT / "samples" / "offset_slider_crank.toml"),
                                       "-o", str(tmp_path), "--format", "dxf", "--jobs", "1"])
    assert result.exit_code == 0, result.output
    folder = tmp_path / "offset_slider_crank"
    for n in (1, 2):
        _audited(folder / f"sheet{n}.dxf")
    assert not list(folder.glob("*.svg"))
