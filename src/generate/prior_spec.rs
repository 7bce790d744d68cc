//! Which prior a run uses, chosen in the library: `--prior` parses into a [`PriorSpec`], `auto`
//! resolves against the model directory, and scene.json's `prior` records the resolved choice so
//! that `edit` reuses exactly what `generate` used.
use super::object::GenError;
use super::prior::SdPrior;
use crate::diffusion::model::{ModelOptions, StableDiffusion};
use crate::diffusion::runtime::Provider;
use crate::diffusion::Error;
use crate::scene::dir;
use std::path::{Path, PathBuf};

/// A prior, as `--prior` names it: `auto`, `shape`, `sd` or `oracle:REF` (a reference PLY for
/// an object, a reference scene directory for a scene).
#[derive(Debug, Clone, PartialEq)]
pub enum PriorSpec {
    Auto,
    Sd,
    Shape,
    Oracle(PathBuf),
}

impl PriorSpec {
    /// Parses `--prior`'s value.
    pub fn parse(s: &str) -> Result<PriorSpec, String> {
        match s {
            "auto" => Ok(PriorSpec::Auto),
            "sd" => Ok(PriorSpec::Sd),
            "shape" => Ok(PriorSpec::Shape),
            _ => match s.strip_prefix("oracle:") {
                Some(p) if !p.is_empty() => Ok(PriorSpec::Oracle(PathBuf::from(p))),
                _ => Err(format!(
                    "'{s}': expected auto, sd, shape or oracle:REF (a reference PLY or scene directory)"
                )),
            },
        }
    }

    /// `auto` made definite: Stable Diffusion when a model directory is known, else the shape
    /// prior. `sd` without models is an error that says how to give them.
    pub fn resolve(&self, models: Option<&Path>) -> Result<PriorSpec, GenError> {
        match (self, models) {
            (PriorSpec::Auto, Some(_)) => Ok(PriorSpec::Sd),
            (PriorSpec::Auto, None) => Ok(PriorSpec::Shape),
            (PriorSpec::Sd, None) => Err(GenError::Prior(Error::Unavailable(
                "the sd prior needs a model directory (--models DIR or DREAMSCENE_MODELS)".into(),
            ))),
            (p, _) => Ok(p.clone()),
        }
    }

    /// scene.json's record of a resolved prior (`auto` is recorded as what it resolves to).
    pub fn record(&self, models: Option<&Path>) -> dir::Prior {
        let show = |p: &Path| Some(p.display().to_string());
        match self.resolve(models).unwrap_or(PriorSpec::Shape) {
            PriorSpec::Sd => dir::Prior {
                kind: "sd".into(),
                models: models.and_then(show),
            },
            PriorSpec::Oracle(r) => dir::Prior {
                kind: "oracle".into(),
                models: show(&r),
            },
            PriorSpec::Auto | PriorSpec::Shape => dir::Prior {
                kind: "shape".into(),
                models: None,
            },
        }
    }

    /// The prior a scene was generated with, from scene.json's record, with the model directory
    /// it needs (`sd`: the recorded one, else `fallback_models`, e.g. DREAMSCENE_MODELS).
    pub fn from_record(
        p: &dir::Prior,
        fallback_models: Option<PathBuf>,
    ) -> Result<(PriorSpec, Option<PathBuf>), GenError> {
        let bad = |m: &str| GenError::Prior(Error::Unavailable(m.to_string()));
        match p.kind.as_str() {
            "shape" => Ok((PriorSpec::Shape, None)),
            "sd" => p
                .models
                .clone()
                .map(PathBuf::from)
                .or(fallback_models)
                .map(|m| (PriorSpec::Sd, Some(m)))
                .ok_or_else(|| {
                    bad("the scene's prior is sd but no model directory is known (set DREAMSCENE_MODELS)")
                }),
            "oracle" => p
                .models
                .clone()
                .map(|m| (PriorSpec::Oracle(PathBuf::from(m)), None))
                .ok_or_else(|| bad("the scene's oracle prior names no reference directory")),
            k => Err(bad(&format!("unknown prior kind `{k}` in scene.json"))),
        }
    }
}

/// The Stable Diffusion prior on the models in `models`, run by `provider` (`--provider`; `auto`
/// resolves for this machine): every command that makes an sd prior (`object`, `generate`,
/// `edit`, `bench`) opens it here, so the provider reaches the model sessions. A pipeline an
/// earlier prior of the same directory and provider gave back is reused ([`super::sd_pool`]).
pub fn open_sd(
    models: &Path,
    provider: Provider,
    prompt: &str,
    edit: Option<&str>,
) -> Result<SdPrior, GenError> {
    let key = super::sd_pool::key(models, provider);
    let sd = match super::sd_pool::take(&key) {
        Some(sd) => sd,
        None => {
            let opts = ModelOptions {
                provider,
                threads: None,
            };
            let sd = StableDiffusion::open(models, &opts).map_err(|msg| {
                GenError::Prior(Error::Model {
                    path: models.to_path_buf(),
                    msg,
                })
            })?;
            super::sd_pool::opened();
            sd
        }
    };
    Ok(SdPrior::new(sd, prompt, edit).pooled(key))
}

impl std::str::FromStr for PriorSpec {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        PriorSpec::parse(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recorded_prior_reads_back_as_the_resolved_one() {
        let models = Path::new("/models/sd21");
        for (spec, m) in [
            (PriorSpec::Auto, Some(models)),
            (PriorSpec::Auto, None),
            (PriorSpec::Sd, Some(models)),
            (PriorSpec::Shape, Some(models)),
            (PriorSpec::Oracle(PathBuf::from("/ref/scene")), None),
        ] {
            let rec = spec.record(m);
            let (back, dir) = PriorSpec::from_record(&rec, None).unwrap();
            assert_eq!(back, spec.resolve(m).unwrap(), "{spec:?} {m:?} -> {rec:?}");
            assert_eq!(dir.as_deref(), (back == PriorSpec::Sd).then_some(models));
        }
        assert_eq!(PriorSpec::Auto.record(None).kind, "shape");
        assert!(PriorSpec::Sd.resolve(None).is_err());
    }

    #[test]
    fn unknown_or_incomplete_records_are_refused_with_a_reason() {
        let rec = |kind: &str, models: Option<&str>| dir::Prior {
            kind: kind.into(),
            models: models.map(str::to_string),
        };
        let fallback = Some(PathBuf::from("/env/models"));
        let (p, m) = PriorSpec::from_record(&rec("sd", None), fallback).unwrap();
        assert_eq!((p, m), (PriorSpec::Sd, Some(PathBuf::from("/env/models"))));
        for (r, why) in [
            (rec("sd", None), "DREAMSCENE_MODELS"),
            (rec("oracle", None), "reference"),
            (rec("dalle", None), "dalle"),
        ] {
            let e = PriorSpec::from_record(&r, None).unwrap_err().to_string();
            assert!(e.contains(why), "{e}");
        }
        assert!(PriorSpec::parse("oracle:").is_err());
        assert_eq!(
            "oracle:/x".parse::<PriorSpec>(),
            Ok(PriorSpec::Oracle(PathBuf::from("/x")))
        );
    }
}
