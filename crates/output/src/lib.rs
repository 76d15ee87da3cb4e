//! Standard output through a checked writer: [`out!`] and [`outln!`]
//! instead of `print!` and `println!`, which panic when the reader is gone
//! (`wai claims | head`, `sweep | head`). Every binary of the workspace
//! writes through it.
//!
//! A closed pipe ends the command quietly, with the status a shell reports
//! for a command stopped by SIGPIPE (141 = 128 + 13): the reader asked for
//! no more, so there is nothing to say. Any other failure to write (a full
//! disk behind a redirection) is an error: a message on standard error and
//! exit status 3, as for any file that cannot be written.

use std::io::{ErrorKind, Write};

/// The exit status of a command whose reader closed the pipe.
pub const CLOSED_PIPE: i32 = 128 + 13;

/// Writes `args` to standard output, or ends the process as the module
/// says.
pub fn write(args: std::fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args) {
        if e.kind() == ErrorKind::BrokenPipe {
            std::process::exit(CLOSED_PIPE);
        }
        // Not through `eprintln!`: it would panic if standard error is
        // gone too.
        let _ = writeln!(std::io::stderr(), "error: cannot write the output: {e}");
        std::process::exit(3);
    }
}

/// `print!` through [`write`].
#[macro_export]
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::write(format_args!($($arg)*))
    };
}

/// `println!` through [`write`].
#[macro_export]
macro_rules! outln {
    () => {
        $crate::write(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}
