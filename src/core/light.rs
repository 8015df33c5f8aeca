//! The lighting interface of the deferred shader: diffuse irradiance and prefiltered specular
//! radiance at a surface point, with backward variants, for the two lights of the method: the
//! global [`PreparedEnv`] ignores the position; [`GridMap`]'s local probes use it. It sits above
//! both, so that neither names the other and an engine learns which light it has from
//! [`LightProbe::kind`] without downcasting. Implementations are shared read-only across rayon
//! threads; gradients go into the caller's (per-thread) [`EnvGrad`].

use glam::DVec3;

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
        self.blended_irradiance(position, normal, ior, DVec3::ZERO)
            .0
    }

    fn irradiance_backward(
        &self,
        position: DVec3,
        normal: DVec3,
        ior: f64,
        grad_out: DVec3,
        _grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        let (_, grad_n, grad_ior) = self.blended_irradiance(position, normal, ior, grad_out);
        (grad_n, grad_ior)
    }

    fn specular(&self, position: DVec3, dir: DVec3, roughness: f64) -> DVec3 {
        if self.occluded(position, dir) {
            self.blended_specular(position, dir, roughness, DVec3::ZERO)
                .0
        } else {
            self.global.specular(dir, roughness)
        }
    }

    fn specular_backward(
        &self,
        position: DVec3,
        dir: DVec3,
        roughness: f64,
        grad_out: DVec3,
        grad: &mut EnvGrad,
    ) -> (DVec3, f64) {
        if self.occluded(position, dir) {
            let (_, grad_dir, grad_r) = self.blended_specular(position, dir, roughness, grad_out);
            (grad_dir, grad_r)
        } else {
            self.global
                .specular_backward(dir, roughness, grad_out, grad)
        }
    }

    fn zero_grad(&self) -> EnvGrad {
        self.global.zero_grad()
    }

    fn kind(&self) -> LightKind<'_> {
        LightKind::GridMap(self)
    }
}
