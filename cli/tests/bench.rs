//! End-to-end tests of `rtc bench` on lavapipe (skipped, saying so, where no adapter exists): on
//! the path-traced Cornell box at 32x32 the table has one row per level, the error falls with the
//! sample count, the CSV, JSON and SVG files are written and parse; a missing or wrong-sized
//! reference is a clear error, never a panic; `--against` prints the checked equal-error time ratio
//! against a synthetic curve, and a malformed curve is a clear error; `--runs` reports the median
//! and the spread.

mod common;

use common::{no_gpu, rtc, s, scratch, text};
use rtc_runtime::image_out::{write_exr, LinearImage};
use std::path::{Path, PathBuf};

fn cornell() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/cornell_path/scene.rt")
        .canonicalize()
        .expect("examples/cornell_path exists")
}

/// RMSE at 1, 4, 16 spp against the scene at 128 spp. The reference shares the levels' first
/// samples, so the expected MSE is σ²(1/n − 1/128): the RMSE ratio from one level to the next is
/// about 0.49 to 0.47 (measured 0.71 from 1 to 4 spp: a pinhole camera takes the pixel centre at
/// 1 spp and jitters above). The test demands a fall of at least 10 % at every level and a ratio
/// below 0.5 from 1 to 16 spp (expected 0.23).
#[test]
fn table_rows_fall_and_files_parse() {
    let dir = scratch("bench", "table");
    let (csv, json, svg) = (dir.join("t.csv"), dir.join("t.json"), dir.join("t.svg"));
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--size",
        "32x32",
        "--reference-spp",
        "128",
        "--spp-list",
        "4,1,16",
        "--csv",
        s(&csv),
        "--json",
        s(&json),
        "--plot",
        s(&svg),
    ]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert!(out.status.success(), "{t}");
    assert!(t.contains("pipelines") && t.contains("not included"), "{t}");

    let csv_text = std::fs::read_to_string(&csv).expect("csv written");
    let lines: Vec<&str> = csv_text.lines().collect();
    assert_eq!(lines.first(), Some(&"spp,ms,rmse,rel_mse,psnr_db"));
    let rows: Vec<Vec<f64>> = lines[1..]
        .iter()
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    assert_eq!(rows.len(), 3, "{csv_text}");
    let spp: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(spp, [1.0, 4.0, 16.0]);
    for pair in rows.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        assert!(
            b[1] > 0.0 && a[1] > 0.0,
            "times must be positive: {csv_text}"
        );
        let ratio = b[2] / a[2];
        assert!(
            ratio > 0.1 && ratio < 0.9,
            "RMSE {} -> {} (ratio {ratio})",
            a[2],
            b[2]
        );
        assert!(b[3] < a[3], "relative MSE must fall: {csv_text}");
    }

    let overall = rows[2][2] / rows[0][2];
    assert!(
        overall < 0.5,
        "RMSE 1 -> 16 spp ratio {overall}: {csv_text}"
    );

    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json written"))
            .expect("valid JSON");
    assert_eq!(value["rows"].as_array().map(Vec::len), Some(3));
    assert_eq!(value["width"], 32);
    assert_eq!(value["reference"], "scene at 128 spp");
    assert!(value["setup"]["pipeline_ms"].as_f64().is_some());
    // The slope is a fit over measured times, so its size depends on the machine (a fixed cost
    // per pass makes it steeper on a fast driver: -1.03 was seen on lavapipe at 32x32). What
    // holds anywhere: it is the least-squares fit of the table's own rows, and error falls as
    // time grows.
    let slope = value["loglog_slope"].as_f64().expect("a slope");
    let pts: Vec<(f64, f64)> = rows.iter().map(|r| (r[1].ln(), r[2].ln())).collect();
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let fitted = sxy / sxx;
    assert!(
        (slope - fitted).abs() < 1e-2 * fitted.abs().max(1.0),
        "slope {slope}, fit of the CSV rows {fitted}: {csv_text}"
    );
    assert!(
        slope < 0.0 && slope.is_finite(),
        "slope {slope}: {csv_text}"
    );

    let svg_text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(svg_text.starts_with("<svg") && svg_text.trim_end().ends_with("</svg>"));
    assert_eq!(svg_text.matches("<circle").count(), 3);
}

#[test]
fn bad_references_are_clear_errors() {
    let dir = scratch("bench", "bad");
    let missing = dir.join("missing.exr");
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--size",
        "32x32",
        "--reference",
        s(&missing),
    ]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(
        t.contains("cannot use the reference") && t.contains("missing.exr"),
        "{t}"
    );
    assert!(!t.contains("panicked"), "{t}");

    let small = dir.join("small.exr");
    write_exr(&small, &LinearImage::filled(8, 8, [0.5, 0.5, 0.5, 1.0])).expect("write");
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--size",
        "32x32",
        "--reference",
        s(&small),
    ]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(
        t.contains("is 8x8 but the bench renders 32x32; give --size 8x8"),
        "{t}"
    );
    assert!(!t.contains("panicked"), "{t}");

    let out = rtc(&["bench", s(&cornell()), "--plot", s(&dir.join("p.png"))]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("must end in `.svg`"));
}

/// `--against`: a synthetic curve in Mitsuba-style CSV (`spp,seconds,rmse`) on the exact power law
/// `t = 10 ms / e²`, a straight line in log-log, so the interpolated time at rtc's RMSE `e` is exactly
/// `10 / e²` ms and the ratio at each level is `ms · e² / 10`. The test recomputes that from the
/// run's own CSV and checks the JSON's ratios, their geometric mean and the printed summary.
#[test]
fn against_prints_the_equal_error_time_ratio_of_a_synthetic_curve() {
    let dir = scratch("bench", "against");
    let curve = dir.join("other.csv");
    let mut text_in = String::from("# synthetic: t = 10 ms / e^2\nspp,seconds,rmse\n");
    for (spp, e) in [(1, 1.0f64), (4, 0.3), (16, 0.1), (64, 0.03), (256, 0.01)] {
        text_in.push_str(&format!("{spp},{},{e}\n", 0.01 / (e * e)));
    }
    std::fs::write(&curve, text_in).expect("write curve");
    let (csv, json, svg) = (dir.join("a.csv"), dir.join("a.json"), dir.join("a.svg"));
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--size",
        "32x32",
        "--reference-spp",
        "64",
        "--spp-list",
        "1,4",
        "--against",
        s(&curve),
        "--csv",
        s(&csv),
        "--json",
        s(&json),
        "--plot",
        s(&svg),
    ]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert!(out.status.success(), "{t}");
    let csv_text = std::fs::read_to_string(&csv).expect("csv written");
    let want: Vec<f64> = csv_text
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().expect("number")).collect();
            v[1] * v[2] * v[2] / 10.0
        })
        .collect();
    assert_eq!(want.len(), 2, "{csv_text}");
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json written"))
            .expect("valid JSON");
    let levels = value["against"]["levels"].as_array().expect("levels");
    assert_eq!(value["against"]["label"], "other");
    assert_eq!(levels.len(), 2);
    for (level, w) in levels.iter().zip(&want) {
        let got = level["ratio"].as_f64().expect("in range");
        // The CSV rounds ms to 3 decimals and the RMSE to 8: 1e-3 relative is ample.
        assert!((got / w - 1.0).abs() < 1e-3, "ratio {got}, want {w}: {t}");
    }
    let geo = (want[0] * want[1]).sqrt();
    let got = value["against"]["ratio_geomean"].as_f64().expect("geomean");
    assert!((got / geo - 1.0).abs() < 1e-3, "geomean {got}, want {geo}");
    assert!(
        t.contains(&format!("equal-error time ratio rtc / other: {got:.3}")),
        "{t}"
    );
    let svg_text = std::fs::read_to_string(&svg).expect("svg written");
    assert_eq!(svg_text.matches("<polyline").count(), 2, "{svg_text}");
}

#[test]
fn a_bad_against_curve_is_a_clear_error_before_rendering() {
    let dir = scratch("bench", "against-bad");
    let curve = dir.join("bad.csv");
    std::fs::write(&curve, "spp,rmse\n1,0.1\n4,0.05\n").expect("write");
    let out = rtc(&["bench", s(&cornell()), "--against", s(&curve)]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(
        t.contains("cannot use the curve") && t.contains("no time column"),
        "{t}"
    );
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--against",
        s(&dir.join("none.csv")),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(!text(&out).contains("panicked"));
}

/// `--runs 3`: every level three times, in rounds; the table and the JSON give the median and the
/// spread, the images of a level's runs are identical (no warning), and 0 runs is a usage error.
#[test]
fn runs_give_the_median_and_the_spread() {
    let dir = scratch("bench", "runs");
    let json = dir.join("r.json");
    let out = rtc(&[
        "bench",
        s(&cornell()),
        "--size",
        "32x32",
        "--reference-spp",
        "16",
        "--spp-list",
        "1,4",
        "--runs",
        "3",
        "--json",
        s(&json),
    ]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert!(out.status.success(), "{t}");
    assert!(t.contains("run 3 of 3"), "{t}");
    assert!(t.contains("ms = median of 3 runs"), "{t}");
    assert!(!t.contains("another image"), "{t}");
    let value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json written"))
            .expect("valid JSON");
    assert_eq!(value["runs"], 3);
    let rows = value["rows"].as_array().expect("rows");
    assert_eq!(rows.len(), 2);
    for row in rows {
        let (lo, ms, hi) = (
            row["ms_min"].as_f64().expect("ms_min"),
            row["ms"].as_f64().expect("ms"),
            row["ms_max"].as_f64().expect("ms_max"),
        );
        assert!(0.0 < lo && lo <= ms && ms <= hi, "{row}");
    }

    let zero = rtc(&["bench", s(&cornell()), "--runs", "0"]);
    assert_eq!(zero.status.code(), Some(2), "{}", text(&zero));
    assert!(text(&zero).contains("--runs"), "{}", text(&zero));
}
