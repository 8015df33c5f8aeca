//! Above storage: who a request comes from and what its account may do — [`auth`] (who a token
//! belongs to, the tokens file), [`limits`] (each account's limits and where they come from),
//! [`quotas`] (the checks and reservations made before work is accepted) and [`admission`]
//! (whether a capture fits a job's process). Refusals are [`crate::domain::refusal::Refusal`]s.

pub mod admission;
pub mod auth;
pub mod limits;
pub mod quotas;
