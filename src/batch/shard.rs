//! Sharding: which worker of N does a scene. The shard of a scene is a pure function of its id
//! (64-bit FNV-1a of the id's bytes, modulo N), so a resubmitted shard redoes exactly its own
//! missing scenes whatever else changed. The shard of a worker comes from `--shard I/N`, a Slurm
//! job array (`SLURM_ARRAY_TASK_ID`, `SLURM_ARRAY_TASK_COUNT`, `SLURM_ARRAY_TASK_MIN`,
//! `SLURM_ARRAY_TASK_STEP`) or a Kubernetes Indexed Job (`JOB_COMPLETION_INDEX` with a count
//! from `--shards N` or `DREAMSCENE_SHARDS`, since Kubernetes does not pass the completions).
use std::fmt;

/// Worker `index` of `count` (0-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// Parses `I/N` with 0 <= I < N.
    pub fn parse(s: &str) -> Result<Shard, String> {
        let bad = || format!("`{s}`: expected I/N with 0 <= I < N, e.g. 0/4");
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let index: u32 = i.trim().parse().map_err(|_| bad())?;
        let count: u32 = n.trim().parse().map_err(|_| bad())?;
        if count == 0 || index >= count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }

    /// Whether the scene `id` is this worker's.
    pub fn owns(&self, id: &str) -> bool {
        shard_of(id, self.count) == self.index
    }
}

/// The shard (0..count) of a scene id.
pub fn shard_of(id: &str, count: u32) -> u32 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in id.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    (h % u64::from(count.max(1))) as u32
}

/// The worker's shard: `explicit` (`--shard`) first, then a Slurm array task, then a Kubernetes
/// completion index with `shards` (`--shards`) or `DREAMSCENE_SHARDS`; `None` when nothing says
/// (the worker then takes every scene it can claim). `env` looks a variable up; an empty value
/// counts as unset.
pub fn resolve(
    explicit: Option<Shard>,
    shards: Option<u32>,
    env: &dyn Fn(&str) -> Option<String>,
) -> Result<Option<Shard>, String> {
    if explicit.is_some() {
        return Ok(explicit);
    }
    let var = |name: &str| env(name).filter(|v| !v.trim().is_empty());
    let num = |name: &str| -> Result<Option<u32>, String> {
        var(name)
            .map(|v| {
                v.trim()
                    .parse::<u32>()
                    .map_err(|_| format!("{name}={v}: expected a whole number"))
            })
            .transpose()
    };
    if let Some(id) = num("SLURM_ARRAY_TASK_ID")? {
        let count = num("SLURM_ARRAY_TASK_COUNT")?
            .ok_or("SLURM_ARRAY_TASK_ID is set without SLURM_ARRAY_TASK_COUNT")?;
        let min = num("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
        let step = num("SLURM_ARRAY_TASK_STEP")?.unwrap_or(1).max(1);
        let index = id
            .checked_sub(min)
            .map(|d| d / step)
            .filter(|&i| i < count)
            .ok_or_else(|| {
                format!(
                    "SLURM_ARRAY_TASK_ID={id} is not one of {count} tasks from {min} in steps \
                     of {step}"
                )
            })?;
        return Ok(Some(Shard { index, count }));
    }
    if let Some(index) = num("JOB_COMPLETION_INDEX")? {
        let count = match shards {
            Some(n) => n,
            None => num("DREAMSCENE_SHARDS")?.ok_or(
                "JOB_COMPLETION_INDEX is set: give the Job's completions as --shards N or \
                 DREAMSCENE_SHARDS",
            )?,
        };
        if index >= count {
            return Err(format!(
                "JOB_COMPLETION_INDEX={index} is not below the shard count {count}"
            ));
        }
        return Ok(Some(Shard { index, count }));
    }
    if shards.is_some() {
        return Err("--shards needs JOB_COMPLETION_INDEX (else use --shard I/N)".into());
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    fn env(pairs: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let m: HashMap<String, String> = pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        move |k: &str| m.get(k).cloned()
    }

    #[test]
    fn every_id_has_exactly_one_shard_and_keeps_it() {
        let ids: Vec<String> = (0..200).map(|i| format!("{i:04}")).collect();
        for n in [1u32, 2, 3, 4, 7] {
            let mut per = vec![0usize; n as usize];
            for id in &ids {
                let owners: Vec<u32> = (0..n)
                    .filter(|&i| Shard { index: i, count: n }.owns(id))
                    .collect();
                assert_eq!(owners.len(), 1, "{id} over {n}");
                assert_eq!(owners[0], shard_of(id, n), "same answer every time");
                per[owners[0] as usize] += 1;
            }
            // A hash spreads 200 ids roughly evenly: no shard under half its share.
            let fair = 200 / n as usize;
            assert!(per.iter().all(|&c| c * 2 >= fair), "{n} shards: {per:?}");
        }
        // FNV-1a is fixed by its definition, not by this build: the empty id's hash is the
        // offset basis, and "a" hashes to 0xaf63dc4c8601ec8c.
        assert_eq!(
            shard_of("", 1_000_003),
            (0xcbf29ce484222325u64 % 1_000_003) as u32
        );
        assert_eq!(
            shard_of("a", 1_000_003),
            (0xaf63dc4c8601ec8cu64 % 1_000_003) as u32
        );
    }

    #[test]
    fn job_completion_index_with_a_count_names_the_shard() {
        let e = env(&[("JOB_COMPLETION_INDEX", "2"), ("DREAMSCENE_SHARDS", "5")]);
        assert_eq!(
            resolve(None, None, &e).unwrap(),
            Some(Shard { index: 2, count: 5 })
        );
        // --shards wins over the variable.
        assert_eq!(
            resolve(None, Some(3), &e).unwrap(),
            Some(Shard { index: 2, count: 3 })
        );
        let missing = resolve(None, None, &env(&[("JOB_COMPLETION_INDEX", "0")])).unwrap_err();
        assert!(missing.contains("DREAMSCENE_SHARDS"), "{missing}");
        let over = resolve(None, Some(2), &env(&[("JOB_COMPLETION_INDEX", "2")])).unwrap_err();
        assert!(over.contains("JOB_COMPLETION_INDEX=2"), "{over}");
        // Indexed Job pods 0..N together cover every id once.
        let ids: Vec<String> = (0..50).map(|i| format!("scene-{i}")).collect();
        let mut seen = vec![0; ids.len()];
        for pod in 0..4 {
            let idx = pod.to_string();
            let s = resolve(
                None,
                None,
                &env(&[("JOB_COMPLETION_INDEX", &idx), ("DREAMSCENE_SHARDS", "4")]),
            )
            .unwrap()
            .unwrap();
            for (k, id) in ids.iter().enumerate() {
                seen[k] += usize::from(s.owns(id));
            }
        }
        assert!(seen.iter().all(|&c| c == 1));
    }

    #[test]
    fn slurm_arrays_with_offsets_and_steps() {
        let e = env(&[
            ("SLURM_ARRAY_TASK_ID", "3"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
        ]);
        assert_eq!(
            resolve(None, None, &e).unwrap(),
            Some(Shard { index: 3, count: 4 })
        );
        let e = env(&[
            ("SLURM_ARRAY_TASK_ID", "7"),
            ("SLURM_ARRAY_TASK_COUNT", "3"),
            ("SLURM_ARRAY_TASK_MIN", "1"),
            ("SLURM_ARRAY_TASK_STEP", "3"),
        ]);
        assert_eq!(
            resolve(None, None, &e).unwrap(),
            Some(Shard { index: 2, count: 3 })
        );
        assert!(resolve(None, None, &env(&[("SLURM_ARRAY_TASK_ID", "1")])).is_err());
        // An explicit --shard wins; empty variables are unset.
        let explicit = Some(Shard { index: 0, count: 2 });
        assert_eq!(resolve(explicit, None, &e).unwrap(), explicit);
        let empty = env(&[("SLURM_ARRAY_TASK_ID", ""), ("JOB_COMPLETION_INDEX", " ")]);
        assert_eq!(resolve(None, None, &empty).unwrap(), None);
        assert!(Shard::parse("4/4").is_err() && Shard::parse("x").is_err());
        assert_eq!(Shard::parse("1/4").unwrap(), Shard { index: 1, count: 4 });
    }
}
