//! `rtc bench --against FILE`: the equal-error time ratio against another renderer's curve.
//!
//! The other renderer's error-against-time curve is read from a file before anything renders:
//!
//! - **CSV**: a header line naming the columns, then one line per measured level. It must have a
//!   `rmse` column and a time column, `ms` (milliseconds) or `seconds`; a `spp` column is shown if
//!   present, other columns are ignored (so `rtc bench --csv` output is a valid curve). Empty lines
//!   and lines starting with `#` are skipped.
//! - **JSON**: an object with a `rows` array (as `rtc bench --json` writes), or a bare array, of
//!   objects with `rmse` and `ms` or `seconds` (and optionally `spp`).
//!
//! A curve needs at least two points with positive, finite time and error. The ratio is computed
//! on the log-log curves: for each of rtc's levels whose RMSE lies within the other curve's range,
//! the other renderer's time at that same RMSE is interpolated linearly in `(ln rmse, ln time)`
//! between the two of its points that bracket it (in time order, the first bracketing segment), and
//! the ratio is `rtc time / other time` (below 1: rtc reaches that error sooner). Levels outside the
//! other curve's error range are reported as such, not extrapolated. The summary is the geometric
//! mean of the ratios in range.
//!
//! Guarantees: a file that is missing, unreadable or malformed is an `Err` with a message naming
//! the line or field; nothing here panics on input.

use std::fmt::Write as _;
use std::path::Path;

/// One point of a curve: time in milliseconds and RMSE (and the samples per pixel if known).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    /// Samples per pixel, when the file gives them.
    pub spp: Option<f64>,
    /// Time, ms.
    pub ms: f64,
    /// Root-mean-square error against the reference.
    pub rmse: f64,
}

/// Another renderer's curve as read from a file.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// What to call it in the output (the file's stem).
    pub label: String,
    /// Its points with positive, finite time and error, in time order.
    pub points: Vec<Point>,
}

/// The ratio at one of rtc's levels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Level {
    /// rtc's samples per pixel.
    pub spp: u32,
    /// rtc's time, ms.
    pub ms: f64,
    /// rtc's RMSE.
    pub rmse: f64,
    /// The other renderer's interpolated time at this RMSE, ms (`None`: outside its range).
    pub other_ms: Option<f64>,
}

impl Level {
    /// rtc's time over the other's at equal error.
    pub fn ratio(&self) -> Option<f64> {
        self.other_ms.map(|o| self.ms / o)
    }
}

/// Reads a curve from a CSV or JSON file (by its extension; `.json` is JSON, anything else CSV).
pub fn read(path: &Path) -> Result<Curve, String> {
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let label = path
        .file_stem()
        .map_or_else(|| "other".to_string(), |s| s.to_string_lossy().into_owned());
    let is_json = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let points = if is_json {
        parse_json(&text)?
    } else {
        parse_csv(&text)?
    };
    curve(label, points)
}

/// Keeps the usable points (positive, finite), in time order; at least two.
fn curve(label: String, points: Vec<Point>) -> Result<Curve, String> {
    let mut points: Vec<Point> = points
        .into_iter()
        .filter(|p| p.ms > 0.0 && p.rmse > 0.0 && p.ms.is_finite() && p.rmse.is_finite())
        .collect();
    if points.len() < 2 {
        return Err(format!(
            "a curve needs at least two points with positive time and RMSE; found {}",
            points.len()
        ));
    }
    points.sort_by(|a, b| a.ms.total_cmp(&b.ms));
    Ok(Curve { label, points })
}

/// Parses the CSV form (see the module docs).
pub fn parse_csv(text: &str) -> Result<Vec<Point>, String> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let Some((_, header)) = lines.next() else {
        return Err("the file is empty (expected a header such as `spp,seconds,rmse`)".into());
    };
    let names: Vec<String> = header
        .split(',')
        .map(|c| c.trim().to_ascii_lowercase())
        .collect();
    let col = |name: &str| names.iter().position(|n| n == name);
    let rmse = col("rmse").ok_or_else(|| {
        format!("the header `{header}` has no `rmse` column (expected e.g. `spp,seconds,rmse`)")
    })?;
    let (time, scale) = match (col("ms"), col("seconds")) {
        (Some(c), _) => (c, 1.0),
        (None, Some(c)) => (c, 1000.0),
        (None, None) => {
            return Err(format!(
                "the header `{header}` has no time column: name it `ms` or `seconds`"
            ))
        }
    };
    let spp = col("spp");
    let mut points = Vec::new();
    for (i, line) in lines {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        let cell = |c: usize, what: &str| -> Result<f64, String> {
            let v = cells
                .get(c)
                .ok_or_else(|| format!("line {}: no `{what}` value (column {})", i + 1, c + 1))?;
            v.parse::<f64>()
                .map_err(|_| format!("line {}: `{v}` is not a number ({what})", i + 1))
        };
        points.push(Point {
            spp: spp.map(|c| cell(c, "spp")).transpose()?,
            ms: cell(time, names[time].as_str())? * scale,
            rmse: cell(rmse, "rmse")?,
        });
    }
    Ok(points)
}

/// Parses the JSON form (see the module docs).
pub fn parse_json(text: &str) -> Result<Vec<Point>, String> {
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("not valid JSON: {e}"))?;
    let rows = match &value {
        serde_json::Value::Array(rows) => rows,
        serde_json::Value::Object(o) => match o.get("rows") {
            Some(serde_json::Value::Array(rows)) => rows,
            _ => return Err("expected an array of rows, or an object with a `rows` array".into()),
        },
        _ => return Err("expected an array of rows, or an object with a `rows` array".into()),
    };
    let mut points = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        let num = |k: &str| row.get(k).and_then(serde_json::Value::as_f64);
        let ms = match (num("ms"), num("seconds")) {
            (Some(ms), _) => ms,
            (None, Some(s)) => s * 1000.0,
            (None, None) => {
                return Err(format!(
                    "row {i}: no numeric `ms` or `seconds` (expected e.g. {{\"spp\": 4, \
                     \"seconds\": 0.5, \"rmse\": 0.1}})"
                ))
            }
        };
        let rmse = num("rmse").ok_or_else(|| format!("row {i}: no numeric `rmse`"))?;
        points.push(Point {
            spp: num("spp"),
            ms,
            rmse,
        });
    }
    Ok(points)
}

/// The other curve's time at error `e`, interpolated on its log-log polyline; `None` when no
/// segment brackets `e`.
pub fn time_at(curve: &Curve, e: f64) -> Option<f64> {
    if !(e > 0.0 && e.is_finite()) {
        return None;
    }
    let le = e.ln();
    for w in curve.points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ea, eb) = (a.rmse.ln(), b.rmse.ln());
        let (lo, hi) = if ea <= eb { (ea, eb) } else { (eb, ea) };
        if le < lo || le > hi {
            continue;
        }
        if ea == eb {
            return Some(a.ms.min(b.ms));
        }
        let f = (le - ea) / (eb - ea);
        return Some((a.ms.ln() + f * (b.ms.ln() - a.ms.ln())).exp());
    }
    None
}

/// The ratio at each of rtc's `(spp, ms, rmse)` levels.
pub fn levels(curve: &Curve, ours: &[(u32, f64, f64)]) -> Vec<Level> {
    ours.iter()
        .map(|&(spp, ms, rmse)| Level {
            spp,
            ms,
            rmse,
            other_ms: if ms > 0.0 && ms.is_finite() {
                time_at(curve, rmse)
            } else {
                None
            },
        })
        .collect()
}

/// Geometric mean of the ratios in range (`None` if none is).
pub fn geomean(levels: &[Level]) -> Option<f64> {
    let logs: Vec<f64> = levels
        .iter()
        .filter_map(Level::ratio)
        .filter(|r| *r > 0.0 && r.is_finite())
        .map(f64::ln)
        .collect();
    (!logs.is_empty()).then(|| (logs.iter().sum::<f64>() / logs.len() as f64).exp())
}

/// The printed report: one line per level and the summary.
pub fn report(curve: &Curve, levels: &[Level]) -> String {
    let mut s = format!(
        "\nequal-error time against {} ({} points, RMSE {:.5} to {:.5}), interpolated on the \
         log-log curves:\n{:>7} {:>12} {:>12} {:>14} {:>9}\n",
        curve.label,
        curve.points.len(),
        curve
            .points
            .iter()
            .map(|p| p.rmse)
            .fold(f64::INFINITY, f64::min),
        curve.points.iter().map(|p| p.rmse).fold(0.0, f64::max),
        "spp",
        "rtc ms",
        "RMSE",
        "other ms",
        "ratio"
    );
    for l in levels {
        match l.other_ms {
            Some(o) => {
                let _ = writeln!(
                    s,
                    "{:>7} {:>12.2} {:>12.6} {:>14.2} {:>9.3}",
                    l.spp,
                    l.ms,
                    l.rmse,
                    o,
                    l.ms / o
                );
            }
            None => {
                let _ = writeln!(
                    s,
                    "{:>7} {:>12.2} {:>12.6} {:>14} {:>9}",
                    l.spp, l.ms, l.rmse, "out of range", "-"
                );
            }
        }
    }
    match geomean(levels) {
        Some(g) => {
            let _ = writeln!(
                s,
                "equal-error time ratio rtc / {}: {g:.3} (geometric mean over {} levels; below 1 \
                 means rtc is faster)",
                curve.label,
                levels.iter().filter(|l| l.other_ms.is_some()).count()
            );
        }
        None => {
            let _ = writeln!(
                s,
                "equal-error time ratio rtc / {}: none of rtc's errors lies within its curve's \
                 range",
                curve.label
            );
        }
    }
    s
}

/// The comparison as JSON (for `rtc bench --json`).
pub fn json(curve: &Curve, levels: &[Level]) -> serde_json::Value {
    serde_json::json!({
        "label": curve.label,
        "points": curve.points.iter().map(|p| serde_json::json!({
            "spp": p.spp, "ms": p.ms, "rmse": p.rmse,
        })).collect::<Vec<_>>(),
        "levels": levels.iter().map(|l| serde_json::json!({
            "spp": l.spp, "ms": l.ms, "rmse": l.rmse, "other_ms": l.other_ms, "ratio": l.ratio(),
        })).collect::<Vec<_>>(),
        "ratio_geomean": geomean(levels),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `t = 100 ms / e²` sampled at four errors, with a Mitsuba-style header in seconds.
    fn power_law_csv() -> String {
        let mut s = String::from("# synthetic\nspp,seconds,rmse\n");
        for (spp, e) in [(1, 0.4f64), (4, 0.2), (16, 0.1), (64, 0.05)] {
            let _ = writeln!(s, "{spp},{},{e}", 0.1 / (e * e));
        }
        s
    }

    #[test]
    fn a_power_law_is_interpolated_exactly_and_the_ratio_is_checked() {
        let c = curve("m".into(), parse_csv(&power_law_csv()).expect("parses")).expect("curve");
        assert_eq!(c.points.len(), 4);
        // Between points: still on the power law (a straight line in log-log).
        let t = time_at(&c, 0.3).expect("in range");
        assert!((t - 100.0 / 0.09).abs() < 1e-6 * t, "{t}");
        assert_eq!(time_at(&c, 0.5), None);
        assert_eq!(time_at(&c, 0.01), None);
        // rtc takes 2x the other's time at 0.3 and 0.5x at 0.1; 0.9 is out of range.
        let ours = [(1, 2.0 * t, 0.3), (4, 0.5 * 10_000.0, 0.1), (16, 7.0, 0.9)];
        let l = levels(&c, &ours);
        assert!((l[0].ratio().expect("in range") - 2.0).abs() < 1e-9);
        assert!((l[1].ratio().expect("in range") - 0.5).abs() < 1e-9);
        assert_eq!(l[2].ratio(), None);
        assert!((geomean(&l).expect("two") - 1.0).abs() < 1e-9);
        let text = report(&c, &l);
        assert!(text.contains("out of range"), "{text}");
        assert!(text.contains("rtc / m: 1.000"), "{text}");
    }

    #[test]
    fn rtc_csv_and_json_are_curves_and_bad_files_say_why() {
        let rtc = "spp,ms,rmse,rel_mse,psnr_db\n1,10.0,0.2,0.1,14\n4,40.0,0.1,0.05,20\n";
        let p = parse_csv(rtc).expect("rtc's own CSV");
        assert_eq!(p[1].ms, 40.0);
        let j = parse_json(
            r#"{"rows": [{"spp": 1, "ms": 10.0, "rmse": 0.2}, {"seconds": 0.04, "rmse": 0.1}]}"#,
        )
        .expect("json");
        assert_eq!(j[1].ms, 40.0);
        assert!(parse_csv("spp,rmse\n1,0.1\n")
            .unwrap_err()
            .contains("no time column"));
        assert!(parse_csv("spp,ms,rmse\n1,x,0.1\n")
            .unwrap_err()
            .contains("line 2: `x` is not a number"));
        assert!(parse_json("[{\"ms\": 1}]")
            .unwrap_err()
            .contains("row 0: no numeric `rmse`"));
        assert!(curve("x".into(), p[..1].to_vec())
            .unwrap_err()
            .contains("at least two"));
    }
}
