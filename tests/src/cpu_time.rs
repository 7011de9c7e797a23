//! CPU time of this process for the benchmarks (on a shared machine wall time would
//! measure the neighbours), and its peak memory.

use std::time::Duration;

/// CPU time used so far by every thread of this process, live or ended, from the
/// process CPU-time clock (`clock_gettime(CLOCK_PROCESS_CPUTIME_ID)`), which Linux keeps
/// to the nanosecond: the per-thread scheduler statistics in `/proc` advance only at
/// scheduler ticks, so a render of a few milliseconds read as 4, 8 or 12 ms.
pub fn process_cpu_time() -> Option<Duration> {
    let now = rustix::time::clock_gettime(rustix::time::ClockId::ProcessCPUTime);
    Some(Duration::new(
        u64::try_from(now.tv_sec).ok()?,
        u32::try_from(now.tv_nsec).ok()?,
    ))
}

/// The most memory the process has held at once (its peak resident set), in bytes, where
/// Linux tells it.
pub fn peak_resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}
