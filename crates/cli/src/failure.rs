//! The failure of a subcommand with its exit code (0 success; 1 the map or
//! a file's content is invalid; 2 bad usage; 3 a file could not be read or
//! written), and the progress bars of long commands (on standard error).

/// The progress bar of long commands (on standard error): elapsed time, a
/// bar of `len` steps, a message.
pub fn progress_bar(len: u64) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar
}

/// The scan localizer of `map`, preprocessed with a progress bar on
/// standard error (its stages: cells, signatures, tree); refused as
/// [`wai_scan::ScanLocalizer::try_new`] refuses.
pub fn scan_localizer(
    map: &wai_map::Map,
    opts: wai_scan::Options,
) -> Result<wai_scan::ScanLocalizer, wai_scan::TooLarge> {
    let bar = progress_bar(1);
    let loc = wai_scan::ScanLocalizer::try_new_with_progress(map, opts, &|stage, done, total| {
        bar.set_length(total.max(1) as u64);
        bar.set_position(done as u64);
        bar.set_message(format!("preprocessing: {stage} {done} of {total}"));
    });
    bar.finish_and_clear();
    loc
}

/// A failure with its exit code.
#[derive(Debug)]
pub struct Failure {
    pub code: u8,
    pub message: String,
}

impl Failure {
    pub fn invalid(message: impl Into<String>) -> Self {
        Failure {
            code: 1,
            message: message.into(),
        }
    }
    pub fn usage(message: impl Into<String>) -> Self {
        Failure {
            code: 2,
            message: message.into(),
        }
    }
    pub fn io(message: impl Into<String>) -> Self {
        Failure {
            code: 3,
            message: message.into(),
        }
    }
}

/// A progress bar on standard error: `what` before it, `unit` after the
/// counts.
pub fn counted_bar(what: &'static str, unit: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(&format!(
            "{{msg}} {{bar:40}} {{pos}}/{{len}} {unit} ({{eta}})"
        ))
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar.set_message(what);
    bar
}
