//! Terminal niceties of the `ps30` binary (not part of the library): colour
//! for status words and progress bars on stderr.
//!
//! Colour follows `--color`: `never`, `always`, or `auto` (the default):
//! only when the stream is a terminal and `NO_COLOR` is unset or empty
//! (<https://no-color.org>; an explicit `--color always` wins over it).
//! Progress shows only when stderr is a terminal and `--quiet` is not given,
//! and only for work that has already taken more than a second, so quick
//! commands and CI logs never see a bar.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// How long work runs before a bar appears.
const DELAY: Duration = Duration::from_secs(1);

/// `--color`: when to colour output.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ColorWhen {
    /// On a terminal, unless `NO_COLOR` is set.
    #[default]
    Auto,
    /// Always, even into a pipe or a file, and whatever `NO_COLOR` says.
    Always,
    /// Never.
    Never,
}

impl ColorWhen {
    /// Whether a stream that `is_terminal` or not takes colour.
    fn applies(self, is_terminal: bool) -> bool {
        match self {
            ColorWhen::Always => true,
            ColorWhen::Never => false,
            ColorWhen::Auto => {
                is_terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
            }
        }
    }
}

/// Output decisions for one run of the binary.
#[derive(Clone, Copy, Debug)]
pub struct Ui {
    /// `--quiet`: results and problems only; no progress, notes or
    /// "wrote …" lines.
    pub quiet: bool,
    /// Colour status words on stdout.
    pub color_stdout: bool,
    /// Colour diagnostics on stderr.
    pub color_stderr: bool,
    /// Progress bars on stderr.
    pub progress: bool,
}

impl Ui {
    /// The decisions for `--quiet` and `--color` on this process's streams.
    pub fn new(quiet: bool, color: ColorWhen) -> Ui {
        Ui {
            quiet,
            color_stdout: color.applies(std::io::stdout().is_terminal()),
            color_stderr: color.applies(std::io::stderr().is_terminal()),
            progress: !quiet && std::io::stderr().is_terminal(),
        }
    }

    /// `text` with its status words coloured (green for good, red for bad)
    /// when stdout takes colour; unchanged otherwise.
    pub fn highlight(&self, text: &str) -> String {
        if !self.color_stdout {
            return text.to_string();
        }
        const GOOD: [&str; 5] = ["agree", "ok", "yes", "within limits", "same"];
        const BAD: [&str; 8] = [
            "DISAGREE",
            "UNEXPECTED",
            "EXCEEDS the limits",
            "MAY EXCEED",
            "DIFFERENT",
            "OVER",
            "NO",
            "NOT",
        ];
        let boundary = |c: Option<char>| c.is_none_or(|c| !c.is_alphanumeric() && c != '_');
        let mut out = String::with_capacity(text.len() + 64);
        let mut prev = None;
        let mut rest = text;
        'scan: while let Some(c) = rest.chars().next() {
            if boundary(prev) {
                for (words, colour) in [(&GOOD[..], "32"), (&BAD[..], "31;1")] {
                    for w in words {
                        if let Some(after) = rest.strip_prefix(w) {
                            if boundary(after.chars().next()) {
                                out.push_str(&format!("\x1b[{colour}m{w}\x1b[0m"));
                                prev = w.chars().last();
                                rest = after;
                                continue 'scan;
                            }
                        }
                    }
                }
            }
            out.push(c);
            prev = Some(c);
            rest = &rest[c.len_utf8()..];
        }
        out
    }

    /// A bar for `total` steps that stays hidden until the work has taken
    /// more than a second.
    pub fn bar(&self, message: &str, total: u64) -> Bar {
        let pb = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::hidden());
        pb.set_style(
            ProgressStyle::with_template("{msg:24} [{bar:32}] {percent:>3}% {elapsed}")
                .expect("valid template")
                .progress_chars("=> "),
        );
        pb.set_message(message.to_string());
        Bar {
            pb,
            enabled: self.progress,
            shown: false,
            start: Instant::now(),
        }
    }

    /// A spinner for one long call without steps: it appears after a second
    /// and ticks on its own thread until dropped.
    pub fn spinner(&self, message: &str) -> Spinner {
        let pb = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        pb.set_style(
            ProgressStyle::with_template("{spinner} {msg} {elapsed}").expect("valid template"),
        );
        pb.set_message(message.to_string());
        let done = Arc::new(AtomicBool::new(false));
        let thread = self.progress.then(|| {
            let (pb, done) = (pb.clone(), done.clone());
            std::thread::spawn(move || {
                let start = Instant::now();
                while !done.load(Ordering::Acquire) {
                    let left = DELAY.saturating_sub(start.elapsed());
                    if left.is_zero() {
                        pb.set_draw_target(ProgressDrawTarget::stderr());
                        pb.enable_steady_tick(Duration::from_millis(120));
                        return;
                    }
                    std::thread::park_timeout(left);
                }
            })
        });
        Spinner { pb, done, thread }
    }
}

/// A progress bar (see [`Ui::bar`]); cleared when dropped.
pub struct Bar {
    pb: ProgressBar,
    enabled: bool,
    shown: bool,
    start: Instant,
}

impl Bar {
    /// Sets the position and, for multi-stage work, the stage's message.
    pub fn set(&mut self, message: Option<&str>, done: u64, total: u64) {
        if let Some(m) = message {
            self.pb.set_message(m.to_string());
        }
        self.pb.set_length(total);
        self.pb.set_position(done);
        if self.enabled && !self.shown && self.start.elapsed() > DELAY {
            self.pb.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        self.pb.finish_and_clear();
    }
}

/// A spinner (see [`Ui::spinner`]); stopped and cleared when dropped.
pub struct Spinner {
    pb: ProgressBar,
    done: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Drop for Spinner {
    fn drop(&mut self) {
        self.done.store(true, Ordering::Release);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
        self.pb.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn highlight_colours_whole_words_only() {
        let ui = Ui {
            quiet: false,
            color_stdout: true,
            color_stderr: false,
            progress: false,
        };
        let s = ui.highlight("verdict: within limits\nbook ok, NOTE: DISAGREE\n");
        assert!(s.contains("\x1b[32mwithin limits\x1b[0m"));
        assert!(s.contains("book \x1b[32mok\x1b[0m,"));
        assert!(s.contains("NOTE"), "NOT inside NOTE stays plain: {s}");
        assert!(s.contains("\x1b[31;1mDISAGREE\x1b[0m"));
        let plain = Ui {
            color_stdout: false,
            ..ui
        };
        assert_eq!(plain.highlight("ok"), "ok");
    }
}
