"""Cases from files, dicts and text; overrides as --set; writing back (issue 32, 1)."""

import os

import pytest
import sloshsph
from conftest import CASES, cli


def test_file_case_reads_as_the_program_reads_it(tmp_path):
    case = sloshsph.Case.from_file(os.path.join(CASES, "liu_lin_2008.toml"))
    assert case.name == "liu_lin_2008"
    assert case["tank.length"] == pytest.approx(0.57)
    case.set("time.end", 2.5).set("probes.gauge.0.x", 0.02)
    assert case["time.end"] == 2.5
    assert case["probes.gauge.0.x"] == 0.02
    resolved = case.resolved()
    assert resolved["time.end"] == 2.5
    assert "dt" in resolved.to_dict()["time"]  # defaults filled in


def test_dict_round_trip_and_write_back(tmp_path):
    original = sloshsph.Case.from_file(os.path.join(CASES, "tait2005_screens.toml"))
    tables = original.to_dict()
    again = sloshsph.Case.from_dict(tables, name="tait")
    assert again.to_dict() == tables
    assert again.resolved().to_dict() == original.resolved().to_dict()
    path = tmp_path / "written.toml"
    again.set("time.end", 0.5).write(path)
    written = sloshsph.Case.from_file(path)
    assert written["time.end"] == 0.5
    assert written["screens.0.model"] == tables["screens"][0]["model"]


def test_toml_values_keep_their_types():
    case = sloshsph.Case.from_dict({
        "title": 'quote " and backslash \\ and tab \t',
        "tank": {"shape": "rectangle", "length": 0.6, "height": 0.4},
        "fill": {"depth": 0.12},
        "particles": {"dp": 0.01, "wall_layers": 3},
        "time": {"end": 1.0, "dt": 1e-3, "adaptive": False},
        "probes": {"gauge": [{"name": "left", "x": 0.01}, {"name": "right", "x": 0.59}]},
    })
    d = case.to_dict()
    assert d["title"] == 'quote " and backslash \\ and tab \t'
    assert isinstance(d["particles"]["wall_layers"], int)
    assert isinstance(d["tank"]["length"], float) and d["time"]["dt"] == 1e-3
    assert d["time"]["adaptive"] is False
    assert [g["name"] for g in d["probes"]["gauge"]] == ["left", "right"]
    case.validate()
    with pytest.raises(sloshsph.CaseError) as info:
        case.copy().set("probes.gauge.0.name", "a b").validate()
    assert info.value.key == "probes.gauge.0.name"
    case.validate()  # the copy's override did not reach the original


def test_set_text_takes_a_bare_word_as_the_program_does():
    case = sloshsph.Case.from_file(os.path.join(CASES, "hydrostatic.toml"))
    case.set_text("tank.shape=rectangle")
    assert case["tank.shape"] == "rectangle"
    with pytest.raises(sloshsph.CaseError, match="expected KEY=VALUE"):
        case.set_text("nonsense")
    assert case.overrides == ["tank.shape=rectangle"]  # the bad one was not kept


def test_default_case_is_the_programs():
    case = sloshsph.Case.default()
    assert case.name == "default"
    assert case["tank.length"] == pytest.approx(0.57)


def test_modes_and_tune_match_the_program():
    import json

    path = os.path.join(CASES, "building_sf_10mg.toml")
    code, out, err = cli("modes", path, "--json", "--tank-damping", "0.0275")
    assert code == 0, err
    assert sloshsph.modes(path, tank_damping=[0.0275]) == json.loads(out)  # the same JSON, every digit
    code, out, err = cli("tune", os.path.join(CASES, "liu_lin_2008.toml"), "--target-omega", "5.5", "--mass", "200",
                         "--json")
    assert code == 0, err
    expected = json.loads(out)
    got = sloshsph.tune(os.path.join(CASES, "liu_lin_2008.toml"), 5.5, mass=200)
    assert got.keys() == expected.keys()
    for key in expected:
        assert got[key] == pytest.approx(expected[key], rel=1e-9)  # the program prints 10 digits


def test_linear_matches_the_program(tmp_path):
    import csv

    path = os.path.join(CASES, "clean_tank_forced.toml")
    out_csv = str(tmp_path / "linear.csv")
    code, out, err = cli("linear", path, "--out", out_csv)
    assert code == 0, err
    with open(out_csv) as f:
        rows = list(csv.DictReader(f))
    got = sloshsph.linear(path)
    assert got["damping_model"] == "boundary-layer"
    assert got["modes"][0]["zeta"] == pytest.approx(5.263e-4, rel=1e-3)  # docs/physics.md
    series = got["series"]
    assert len(series["time"]) == len(rows)
    for name in ("eta:left", "eta:right", "F_w", "F_sw"):
        for k in (100, len(rows) - 1):
            assert series[name][k] == pytest.approx(float(rows[k][name]), rel=1e-8, abs=1e-12)  # 10 digits
    with pytest.raises(sloshsph.CaseError, match="pitch is not implemented"):
        sloshsph.linear(os.path.join(CASES, "shao_pitch.toml"))
    with pytest.raises(sloshsph.CaseError, match="is not auto, none, boundary-layer"):
        sloshsph.linear(path, damping="lots")
    # The Tait tank's two Ergun screens act on the modes unless screens=False (a clean tank).
    tait = os.path.join(CASES, "tait2005_screens.toml")
    screened = sloshsph.linear(tait, screens=True, modes=3)
    assert [round(s["x"], 4) for s in screened["screens"]] == [0.3864, 0.5796]
    assert screened["screens"][0]["loss_coefficient"] == pytest.approx(1.05, rel=0.01)
    clean = sloshsph.linear(tait, screens=False, modes=3)
    assert clean["screens"] == [] and "screens" in clean["ignored"][0]
