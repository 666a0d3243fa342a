"""Design points: ``K,MU[:NAME]`` specs and CSV files; every bad file names its line and column."""

from __future__ import annotations

import os
import re

import pytest

from regimemap.maps import file_points as points_mod
from regimemap.maps.file_points import MAX_POINTS_FILE_BYTES, DesignPoint, parse_point_spec, read_points_csv


def _write(tmp_path, text: str | bytes, name: str = "pts.csv"):
    path = tmp_path / name
    if isinstance(text, str):
        path.write_text(text, encoding="utf-8")
    else:
        path.write_bytes(text)
    return path


# -- good files --------------------------------------------------------------------------------------

def test_minimal_file(tmp_path):
    path = _write(tmp_path, "k,mu\n0.1,0.2\n0.3,0.4\n")
    assert read_points_csv(path) == [DesignPoint(0.1, 0.2), DesignPoint(0.3, 0.4)]


def test_all_columns_any_order_any_case_bom_blanks(tmp_path):
    text = "\ufeff\n\n Name ,KPRIME,Gamma, MU ,k,comment\n\ncaisson-A,-0.6,3,2.3,3.5,ignored\n" \
           "wall,,,0.5,0.1,\n\n"
    pts = read_points_csv(_write(tmp_path, text))
    assert pts == [DesignPoint(3.5, 2.3, "caisson-A", 3.0, -0.6), DesignPoint(0.1, 0.5, "wall")]


def test_crlf_and_quoted_names(tmp_path):
    path = _write(tmp_path, b'k,mu,name\r\n0.1,0.2,"a, b"\r\n1e-3,2E+0,"x""y"\r\n')
    assert read_points_csv(path) == [DesignPoint(0.1, 0.2, "a, b"), DesignPoint(0.001, 2.0, 'x"y')]


def test_empty_fields_past_the_header_are_no_values(tmp_path):
    assert read_points_csv(_write(tmp_path, "k,mu\n0.1,0.2,,\n0.3,0.4, \n")) == [DesignPoint(0.1, 0.2),
                                                                              DesignPoint(0.3, 0.4)]


def test_header_only_is_no_points(tmp_path):
    assert read_points_csv(_write(tmp_path, "k,mu\n")) == []


def test_negative_zero_is_zero(tmp_path):
    (pt,) = read_points_csv(_write(tmp_path, "k,mu\n-0,-0.0\n"))
    assert pt.k == 0.0 and str(pt.k) == "0.0" and str(pt.mu) == "0.0"


def test_path_like_and_str(tmp_path):
    path = _write(tmp_path, "k,mu\n1,2\n")
    assert read_points_csv(str(path)) == read_points_csv(path)


# -- bad files: the message names the file, the line and the column ----------------------------------

BAD_FILES = [
    # (content, message regex after the file name)
    ("", r": empty file; expected a header with columns k,mu$"),
    ("\n\n  \n", r": empty file"),
    ("k,nu\n0.1,0.2\n", r", line 1: missing column\(s\) mu; the header must name k and mu"),
    ("x,y\n0.1,0.2\n", r", line 1: missing column\(s\) k, mu"),
    ("k|mu\n0.1|0.2\n", r", line 1: missing column\(s\) k, mu.*'k\|mu'"),
    ("k;mu\n0,5;abc\n", r", line 2, column mu: mu must be .*got 'abc' \(not a number\)"),
    ("\n\nK,Q\n1,2\n", r", line 3: missing column\(s\) mu"),
    ("k,k,mu\n1,2,3\n", r", line 1: column\(s\) k appear more than once"),
    ("k,mu\n0.1,abc\n", r", line 2, column mu: mu must be a finite number >= 0 \(at most 1e\+100\), got 'abc' \(not a number\)"),
    ("k,mu\n0.1,0.2\nfoo,0.2\n", r", line 3, column k: k must be a finite number >= 0 \(at most 1e\+100\), got 'foo'"),
    ("k,mu\n0.1,0.2\n\n0.3\n", r", line 4, column mu: mu is missing"),
    # a value without a column (an unquoted name with the separator) is not dropped unsaid
    ("k,mu\n0.3,0.6,7,8,9\n", r", line 2: 5 fields, but the header names 2 columns \(a value without a column"),
    ("k,mu,name\n0.3,0.6,pier, head\n", r", line 2: 4 fields, but the header names 3 columns"),
    ("k,mu\n,0.2\n", r", line 2, column k: k is missing"),
    ("k,mu\n-0.1,0.2\n", r", line 2, column k: k must be a finite number >= 0 \(at most 1e\+100\), got '-0.1'$"),
    ("k,mu\n0.1,-1e-9\n", r", line 2, column mu: mu must be a finite number >= 0 \(at most 1e\+100\), got '-1e-9'$"),
    ("k,mu\nnan,0.2\n", r", line 2, column k: k must be a finite number >= 0 \(at most 1e\+100\), got 'nan'$"),
    ("k,mu\n0.1,inf\n", r", line 2, column mu: mu must be a finite number >= 0 \(at most 1e\+100\), got 'inf'$"),
    ("k,mu\n0.1,1e400\n", r", line 2, column mu: mu must be a finite number >= 0 \(at most 1e\+100\), got '1e400'$"),
    ("k,mu\n1_000,1\n", r", line 2, column k: .*got '1_000' \(not a number\)"),
    ("k,mu\n0x10,1\n", r", line 2, column k: .*got '0x10' \(not a number\)"),
    ("k,mu\n١,1\n", r", line 2, column k: .*not a number"),
    ("k,mu,gamma\n0.1,0.2,0\n", r", line 2, column gamma: gamma must be a finite number in \[0.001, 1000\], got '0'$"),
    ("k,mu,gamma\n0.1,0.2,-3\n", r", line 2, column gamma: gamma must be a finite number in \[0.001, 1000\], got '-3'$"),
    ("k,mu,gamma\n0.1,0.2,nan\n", r", line 2, column gamma: gamma must be"),
    ("k,mu,gamma\n0.1,0.2,1e-5\n", r", line 2, column gamma: gamma must be a finite number in \[0.001, 1000\], got '1e-5'$"),
    ("k,mu,gamma\n0.1,0.2,1e4\n", r", line 2, column gamma: .*got '1e4'$"),
    ("k,mu\n1e101,0.2\n", r", line 2, column k: k must be a finite number >= 0 \(at most 1e\+100\), got '1e101'$"),
    ("k,mu,gamma\n0.1,0.2,tall\n", r", line 2, column gamma: .*not a number"),
    ("k,mu,kprime\n0.1,0.2,1.5\n", r", line 2, column kprime: kprime must be a number in \[-1, 1\], got '1.5'$"),
    ("k,mu,kprime\n0.1,0.2,-1.0001\n", r", line 2, column kprime: kprime must be a number in \[-1, 1\]"),
    ("k,mu,kprime\n0.1,0.2,nan\n", r", line 2, column kprime: kprime must be a number in \[-1, 1\]"),
    ('k,mu\n"0.1,0.2\n', r", line 2, column k: .*not a number"),
    ("k,mu\x00\n1,2\n", r", line 1: not CSV text \(NUL bytes; a binary file\?\)"),
    (b"k,mu\n\xff\xfe\x00garbage\n", r": not a UTF-8 text file \(byte 0xff; save it as UTF-8\)$"),
    (bytes(range(256)) * 8, r": not a UTF-8 text file \(byte 0x80; save it as UTF-8\)$"),
    (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", r": not a UTF-8 text file \(byte 0x89; save it as UTF-8\)$"),  # a PNG
    ("k,mu\n" + "1" * 200_000 + ",2\n", r", line 2: not CSV text \(a line longer than 65536 characters\)$"),
    ('k,mu\n"' + ("1" * 1000 + "\n") * 200 + '",2\n', r", line \d+: not CSV text \(field larger than field limit"),
]


@pytest.mark.parametrize("content,message", BAD_FILES, ids=[f"bad{i}" for i in range(len(BAD_FILES))])
def test_bad_file(tmp_path, content, message):
    path = _write(tmp_path, content)
    with pytest.raises(ValueError) as e:
        read_points_csv(path)
    msg = str(e.value)
    assert msg.startswith(str(path)), msg
    assert re.search(message, msg[len(str(path)):]), msg
    assert "\n" not in msg


def test_first_bad_row_wins_and_later_rows_are_not_read(tmp_path):
    path = _write(tmp_path, "k,mu\n0.1,0.2\n-1,0.2\n0.1,x\n")
    with pytest.raises(ValueError, match=r"line 3, column k"):
        read_points_csv(path)


def test_directory_passed_as_file(tmp_path):
    with pytest.raises(ValueError, match=r"^points file '.*' is a folder, not a file$"):
        read_points_csv(tmp_path)


def test_missing_file(tmp_path):
    with pytest.raises(ValueError, match=r"^cannot read points file '.*nope.csv': No such file or directory$"):
        read_points_csv(tmp_path / "nope.csv")


def test_file_too_big_is_refused_before_reading(tmp_path, monkeypatch):
    path = _write(tmp_path, "k,mu\n" + "0.1,0.2\n" * 20)
    monkeypatch.setattr(points_mod, "MAX_POINTS_FILE_BYTES", 50)
    with pytest.raises(ValueError, match=r"is \d+ bytes, more than the limit of 50 bytes"):
        read_points_csv(path)
    assert MAX_POINTS_FILE_BYTES >= 64 * 1024 * 1024


def test_too_many_points(tmp_path, monkeypatch):
    path = _write(tmp_path, "k,mu\n" + "0.1,0.2\n" * 6)
    monkeypatch.setattr(points_mod, "MAX_POINTS", 5)
    with pytest.raises(ValueError, match=r"line 7: more than 5 points \(the limit\)"):
        read_points_csv(path)
    monkeypatch.setattr(points_mod, "MAX_POINTS", 6)
    assert len(read_points_csv(path)) == 6


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_endless_device_is_refused_not_read_forever():
    with pytest.raises(ValueError, match="is a character device, not a regular file"):
        read_points_csv("/dev/zero")


# -- point specs ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("spec,point", [
    ("0.1,0.2", DesignPoint(0.1, 0.2)),
    (" 0.1 , 0.2 ", DesignPoint(0.1, 0.2)),
    ("0.45,0.6:caisson-A", DesignPoint(0.45, 0.6, "caisson-A")),
    ("1,2:a:b", DesignPoint(1.0, 2.0, "a:b")),
    ("0,0", DesignPoint(0.0, 0.0)),
    ("1e-3,2E1", DesignPoint(0.001, 20.0)),
])
def test_point_spec_ok(spec, point):
    assert parse_point_spec(spec) == point


@pytest.mark.parametrize("spec,match", [
    ("", "must be K,MU or K,MU:NAME"),
    ("0.1", "must be K,MU or K,MU:NAME"),
    ("0.1,0.2,0.3", "must be K,MU or K,MU:NAME"),
    (":name", "must be K,MU or K,MU:NAME"),
    ("a,b", r"k must be a finite number >= 0 \(at most 1e\+100\), got 'a' \(not a number\)"),
    ("0.1,b", r"mu must be a finite number >= 0 \(at most 1e\+100\), got 'b'"),
    ("-1,2", r"k must be a finite number >= 0 \(at most 1e\+100\), got '-1'"),
    ("1,-2", r"mu must be a finite number >= 0 \(at most 1e\+100\), got '-2'"),
    ("nan,1", r"k must be a finite number >= 0 \(at most 1e\+100\), got 'nan'"),
    ("1,inf", r"mu must be a finite number >= 0 \(at most 1e\+100\), got 'inf'"),
    ("1e400,1", r"k must be a finite number >= 0 \(at most 1e\+100\), got '1e400'"),
    (",1", r"k is missing"),
])
def test_point_spec_bad(spec, match):
    with pytest.raises(ValueError, match=match) as e:
        parse_point_spec(spec)
    assert repr(spec) in str(e.value)


def test_semicolons_and_decimal_commas_are_read(tmp_path):
    from regimemap.maps.file_points import read_points_table

    f = tmp_path / "european.csv"
    f.write_text("name;k;mu\ncaisson-A;0,5;0,3\nquay;1,25;0,1\n", encoding="utf-8")
    table = read_points_table(f)
    assert [(p.name, p.k, p.mu) for p in table.points] == [("caisson-A", 0.5, 0.3), ("quay", 1.25, 0.1)]
    assert table.lines == [2, 3] and "semicolon" in table.note and "decimal commas" in table.note
    assert read_points_table(tmp_path / "european.csv").points == read_points_csv(f)
