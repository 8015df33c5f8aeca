//! The lighting interface of the deferred shader: diffuse irradiance and prefiltered specular
//! radiance at a surface point, with backward variants, for the two lights of the method: the
//! global [`PreparedEnv`] ignores the position; [`GridMap`]'s local probes use it. It sits above
//! both, so that neither names the other and an engine learns which light it has from
//! [`LightProbe::kind`] without downcasting. Implementations are shared read-only across rayon
//! threads; gradients go into the caller's (per-thread) [`EnvGrad`].
//!
//! A lookup can also be *saved* ([`LightProbe::irradiance_saved`], [`LightProbe::specular_saved`]):
//! a light whose lookup takes no gradient of its own (GridMap's blended probes) returns the
//! lookup's derivatives in its inputs, a [`LookupJacobian`], so that the shader's backward pass
//! applies them instead of looking the light up a second time.

use glam::DVec3;

pub use crate::core::envmap::LookupJacobian;
use crate::core::envmap::{EnvGrad, PreparedEnv};
use crate::core::gridmap::GridMap;

/// What a light is, for a backend that evaluates the known kinds on its own device and calls
/// [`LightProbe`] per pixel for the others.
#[derive(Clone, Copy)]
pub enum LightKind<'a> {
    /// The global environment alone (position-independent).
    Global(&'a PreparedEnv),
    /// GridMap's local probes over the global environment.
    GridMap(&'a GridMap),
    /// Any other light.
    Other,
}

/// What a lookup's forward leaves for its backward.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SavedLookup {
    /// Nothing: the backward asks the light again (it adds the light's own gradient).
    Light,
    /// The lookup's input derivatives; the light takes no gradient from it.
    Jacobian(LookupJacobian),
}

/// Light as seen by the shader.
pub trait LightProbe: Sync {
    /// Diffuse irradiance E_d(n) at `position` for a surface of index `ior` (the IoR matters only
    /// with Fresnel-weighted irradiance).
    fn irradiance(&self, position: DVec3, normal: DVec3, ior: f64) -> DVec3;

    /// Backward of [`Self::irradiance`]: adds into `grad`, returns (dL/d normal, dL/d ior).
    fn irradiance_backward(
        &self,
        position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64);

    /// Prefiltered radiance arriving along `dir` (non-zero, need not be unit) for a Disney roughness.
    fn specular(&self, position: DVec3, dir: DVec3, roughness: f64) -> DVec3;

    /// Backward of [`Self::specular`]: adds into `grad`, returns (dL/d dir, dL/d roughness).
    fn specular_backward(
        &self,
        position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64);

    /// [`Self::irradiance`] with what its backward needs ([`Self::irradiance_backward_saved`]).
    fn irradiance_saved(&self, position: DVec3, normal: DVec3, ior: f64) -> (DVec3, SavedLookup) {
        (self.irradiance(position, normal, ior), SavedLookup::Light)
    }

    /// [`Self::irradiance_backward`] of a saved lookup (the same inputs as its forward).
    fn irradiance_backward_saved(
        &self,
        saved: &SavedLookup,
        position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        match saved {
            SavedLookup::Jacobian(jacobian) => jacobian.backward(grad_out),
            SavedLookup::Light => self.irradiance_backward(position, normal, ior, grad_out, grad),
        }
    }

    /// [`Self::specular`] with what its backward needs ([`Self::specular_backward_saved`]).
    fn specular_saved(&self, position: DVec3, dir: DVec3, roughness: f64) -> (DVec3, SavedLookup) {
        (self.specular(position, dir, roughness), SavedLookup::Light)
    }

    /// [`Self::specular_backward`] of a saved lookup (the same inputs as its forward).
    fn specular_backward_saved(
        &self,
        saved: &SavedLookup,
        position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        match saved {
            SavedLookup::Jacobian(jacobian) => jacobian.backward(grad_out),
            SavedLookup::Light => self.specular_backward(position, dir, roughness, grad_out, grad),
        }
    }

    /// Zero accumulators for this light's gradient.
    fn zero_grad(&self) -> EnvGrad;

    /// What this light is ([`LightKind::Other`] unless it says).
    fn kind(&self) -> LightKind<'_> {
        LightKind::Other
    }
}

impl LightProbe for PreparedEnv {
    fn irradiance(&self, _position: DVec3, normal: DVec3, ior: f64) -> DVec3 {
        PreparedEnv::irradiance(self, normal, ior)
    }

    fn irradiance_backward(
        &self,
        _position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        PreparedEnv::irradiance_backward(self, normal, ior, grad_out, grad)
    }

    fn specular(&self, _position: DVec3, dir: DVec3, roughness: f64) -> DVec3 {
        PreparedEnv::specular(self, dir, roughness)
    }

    fn specular_backward(
        &self,
        _position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        PreparedEnv::specular_backward(self, dir, roughness, grad_out, grad)
    }

    fn zero_grad(&self) -> EnvGrad {
        PreparedEnv::zero_grad(self)
    }

    fn kind(&self) -> LightKind<'_> {
        LightKind::Global(self)
    }
}

impl LightProbe for GridMap {
    fn irradiance(&self, position: DVec3, normal: DVec3, ior: f64) -> DVec3 {
        self.blended_irradiance(position, normal, ior).0
    }

    fn irradiance_backward(
        &self,
        position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        _grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        self.blended_irradiance(position, normal, ior)
            .1
            .backward(grad_out)
    }

    fn irradiance_saved(&self, position: DVec3, normal: DVec3, ior: f64) -> (DVec3, SavedLookup) {
        let (value, jacobian) = self.blended_irradiance(position, normal, ior);
        (value, SavedLookup::Jacobian(jacobian))
    }

    fn specular(&self, position: DVec3, dir: DVec3, roughness: f64) -> DVec3 {
        self.specular_saved(position, dir, roughness).0
    }

    fn specular_backward(
        &self,
        position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        let (_, saved) = self.specular_saved(position, dir, roughness);
        self.specular_backward_saved(&saved, position, dir, roughness, grad_out, grad)
    }

    /// Blocked mirror rays save the blend's Jacobian; escaping ones ([`SavedLookup::Light`])
    /// are the global light's, which takes their gradient.
    fn specular_saved(&self, position: DVec3, dir: DVec3, roughness: f64) -> (DVec3, SavedLookup) {
        if self.occluded(position, dir) {
            let (value, jacobian) = self.blended_specular(position, dir, roughness);
            (value, SavedLookup::Jacobian(jacobian))
        } else {
            (self.global.specular(dir, roughness), SavedLookup::Light)
        }
    }

    fn specular_backward_saved(
        &self,
        saved: &SavedLookup,
        _position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        match saved {
            SavedLookup::Jacobian(jacobian) => jacobian.backward(grad_out),
            SavedLookup::Light => self
                .global
                .specular_backward(dir, roughness, grad_out, grad),
        }
    }

    fn zero_grad(&self) -> EnvGrad {
        self.global.zero_grad()
    }

    fn kind(&self) -> LightKind<'_> {
        LightKind::GridMap(self)
    }
}
