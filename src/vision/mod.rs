//! Scene understanding: the robot looks at its camera image and decides, per object, whether it
//! is stable and whether it is occluded: by reasoning where its knowledge decides, with a small
//! CNN where reasoning cannot decide, and with state constraints learned from reasoning's
//! failures (feature `sim`: the labelled scenes come from the simulator).
//!
//! Pipeline: `scenes` builds risky scenes from a seed; `labels` measures the ground truth
//! physically (stability by simulating the scene untouched, occlusion from the frontal view);
//! `roi` crops and resizes the image regions the labels depend on; `dataset` puts them together
//! in parallel, by seed; `reason` is the classification mode of the knowledge base; `cnn` is the
//! LeNet-sized network; `constraints` learns missing state constraints with `learn`'s trees;
//! `classify` combines them into one classifier whose every decision names its source; `see`
//! lets the sense-plan-act loop judge occlusion from its picture at every look.
//!
//! Invariants: values cross the boundaries typed (scenes, ROIs, labels, axioms), never as
//! program text; everything random is drawn from seeded streams, so a seed determines a dataset,
//! a trained network and a learned constraint.

pub mod scenes;
pub mod labels;
pub(crate) mod roi;
pub mod dataset;
pub mod cnn;
pub mod reason;
pub mod constraints;
pub mod classify;
pub(crate) mod see;
