//! A progress bar on standard error, drawn only when standard error is a terminal: a
//! pipe or a CI log gets the messages and nothing else.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

pub struct Progress {
    label: String,
    total: usize,
    done: usize,
    started: Instant,
    visible: bool,
}

impl Progress {
    /// A bar over `total` steps, visible when standard error is a terminal.
    pub fn new(label: impl Into<String>, total: usize) -> Progress {
        let progress = Progress {
            label: label.into(),
            total,
            done: 0,
            started: Instant::now(),
            visible: std::io::stderr().is_terminal(),
        };
        progress.draw();
        progress
    }

    /// One more step done.
    pub fn step(&mut self) {
        self.done = (self.done + 1).min(self.total);
        self.draw();
    }

    /// Takes the bar off the line, so that a message can be printed; the next step draws
    /// it again.
    pub fn clear(&self) {
        if self.visible {
            eprint!("\r\x1b[K");
        }
    }

    /// Leaves the finished bar on its own line.
    pub fn finish(self) {
        if self.visible {
            eprintln!();
        }
    }

    fn draw(&self) {
        if self.visible {
            eprint!(
                "\r\x1b[K{}",
                line(&self.label, self.done, self.total, self.started.elapsed())
            );
            let _ = std::io::stderr().flush();
        }
    }
}

/// `label [#########-----------] 3/7 4.2 s`
fn line(label: &str, done: usize, total: usize, elapsed: Duration) -> String {
    const WIDTH: usize = 24;
    let filled = (WIDTH * done).checked_div(total).unwrap_or(WIDTH);
    format!(
        "{label} [{}{}] {done}/{total} {:.1} s",
        "#".repeat(filled),
        "-".repeat(WIDTH - filled),
        elapsed.as_secs_f64()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_fills_with_the_steps() {
        assert_eq!(
            line("scene.pov", 1, 4, Duration::from_millis(2345)),
            "scene.pov [######------------------] 1/4 2.3 s"
        );
        assert_eq!(
            line("x", 4, 4, Duration::ZERO),
            "x [########################] 4/4 0.0 s"
        );
    }
}
