//! Progress of long work: a bar on a terminal, a log line every few percent elsewhere (logs, CI),
//! each with the stage, the step, a message (loss, Gaussians) and the time left.
use std::io::IsTerminal;
use std::time::Instant;

/// Reports progress of `total` steps.
pub struct Progress {
    total: u64,
    start: Instant,
    bar: Option<indicatif::ProgressBar>,
    next_log: u64,
    /// Log a line every this many steps off a terminal.
    every: u64,
    quiet: bool,
}

impl Progress {
    /// A reporter for `total` steps; `quiet` prints nothing.
    pub fn new(total: u64, quiet: bool) -> Progress {
        let bar = (!quiet && std::io::stderr().is_terminal()).then(|| {
            let b = indicatif::ProgressBar::new(total);
            b.set_style(
                indicatif::ProgressStyle::with_template(
                    "{bar:30} {pos}/{len} {msg} [{elapsed_precise}, {eta} left]",
                )
                .expect("valid template"),
            );
            b
        });
        Progress {
            total: total.max(1),
            start: Instant::now(),
            bar,
            next_log: 0,
            every: (total / 20).max(1),
            quiet,
        }
    }

    /// Step `done` of the total is finished; `msg` says what it is.
    pub fn update(&mut self, done: u64, msg: &str) {
        if self.quiet {
            return;
        }
        if let Some(b) = &self.bar {
            b.set_position(done);
            b.set_message(msg.to_string());
            return;
        }
        if done >= self.next_log || done == self.total {
            let el = self.start.elapsed().as_secs_f64();
            let left = if done > 0 {
                el / done as f64 * (self.total - done.min(self.total)) as f64
            } else {
                0.0
            };
            eprintln!(
                "[{:>3.0}%] {done}/{} {msg} ({el:.0} s, {left:.0} s left)",
                100.0 * done as f64 / self.total as f64,
                self.total
            );
            self.next_log = done + self.every;
        }
    }

    /// Prints a line without breaking the bar.
    pub fn println(&self, line: &str) {
        if self.quiet {
            return;
        }
        match &self.bar {
            Some(b) => b.println(line),
            None => eprintln!("{line}"),
        }
    }

    /// Ends the bar.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}
