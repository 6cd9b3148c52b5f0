from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"
FOUNDATION = sorted(SAMPLES.glob("*.toml"))


@pytest.fixture(params=FOUNDATION, ids=lambda p: p.stem)
def sample_path(request):
    return request.param
