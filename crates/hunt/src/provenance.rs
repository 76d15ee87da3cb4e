//! Where a run's numbers come from: the commit of the checkout, the UTC
//! date and time and the digest of the binary, stamped on plots (`sweep`) and run records (`wai check --record`)
//! so a reader can tell which code produced them.

/// The short commit of the checkout in the current directory, with
/// `+dirty` when tracked files differ from it; `unknown` outside git.
pub fn commit() -> String {
    let git = |args: &[&str]| {
        std::process::Command::new("git")
            .args(args)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let Some(commit) = git(&["rev-parse", "--short", "HEAD"]) else {
        return "unknown".into();
    };
    // A run from uncommitted changes to tracked files says so.
    let dirty =
        git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty());
    if dirty {
        format!("{commit}+dirty")
    } else {
        commit
    }
}

/// Today's date in UTC, `YYYY-MM-DD`.
pub fn utc_date() -> String {
    civil_date((unix_seconds() / 86_400) as i64)
}

/// The time now in UTC, `YYYY-MM-DDTHH:MM:SSZ` (RFC 3339).
pub fn utc_timestamp() -> String {
    timestamp(unix_seconds())
}

fn unix_seconds() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

fn timestamp(seconds: u64) -> String {
    let (days, s) = (seconds / 86_400, seconds % 86_400);
    format!(
        "{}T{:02}:{:02}:{:02}Z",
        civil_date(days as i64),
        s / 3600,
        s % 3600 / 60,
        s % 60
    )
}

/// The SHA-256 of the running binary, so that a record can say which
/// build made it; `unknown` if the binary cannot be read.
pub fn binary_digest() -> String {
    std::env::current_exe()
        .and_then(std::fs::read)
        .map_or_else(|_| "unknown".to_owned(), |b| wai_map::digest::sha256(&b))
}

/// The civil date of `days` since 1970-01-01 (Howard Hinnant's algorithm).
fn civil_date(days: i64) -> String {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

#[cfg(test)]
mod tests {
    #[test]
    fn civil_dates() {
        assert_eq!(super::civil_date(0), "1970-01-01");
        assert_eq!(super::civil_date(20_417), "2025-11-25");
        assert_eq!(super::civil_date(11_016), "2000-02-29");
        assert_eq!(super::timestamp(1_764_300_000), "2025-11-28T03:20:00Z");
    }
}
