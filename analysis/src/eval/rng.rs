//! `seed()` and `rand()`: POV-Ray's parse-time random streams. Scenes that scatter objects
//! depend on the exact sequence, so this is the same linear congruential generator
//! (multiplier 1812433253, increment 12345, 32-bit state, divided by 2^32 - 1), which was
//! measured against POV-Ray 3.7's output: `rand(seed(0))` is 12345 / (2^32 - 1).

/// Every stream a scene created with `seed()`, by the number `seed()` returned.
#[derive(Debug, Default)]
pub struct RandomStreams {
    states: Vec<u32>,
}

impl RandomStreams {
    /// Creates a stream from a seed already converted to an integer as C's `(int)` would
    /// (the caller does that), and returns its number.
    pub fn seed(&mut self, seed: f64) -> usize {
        self.states.push(seed as i32 as u32);
        self.states.len() - 1
    }

    /// The next number of stream `stream`, in [0, 1]; `None` when no such stream exists.
    pub fn rand(&mut self, stream: f64) -> Option<f64> {
        let index = usize::try_from(stream.trunc() as i64).ok()?;
        let state = self.states.get_mut(index)?;
        *state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
        Some(f64::from(*state) / f64::from(u32::MAX))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sequence_matches_povray() {
        let mut streams = RandomStreams::default();
        let s = streams.seed(0.0) as f64;
        let first: Vec<String> = (0..5)
            .map(|_| format!("{:.15}", streams.rand(s).unwrap()))
            .collect();
        assert_eq!(
            first,
            [
                "0.000002874294297",
                "0.466563684508801",
                "0.249070228833954",
                "0.965876042136428",
                "0.636504033030128"
            ]
        );
        let t = streams.seed(12345.0) as f64;
        assert_eq!(
            format!("{:.15}", streams.rand(t).unwrap()),
            "0.466563684508801"
        );
        assert_eq!(streams.rand(7.0), None);
    }
}
