// SPDX-License-Identifier: LGPL-2.1-or-later
// Normals by principal component analysis of each point's k nearest neighbours (Sec. 2.1).
// Design: docs/design/neighbourhoods.md.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

struct NormalOptions
{
    /// Neighbours used per point, 2 to Neighbourhoods::k(); 0 for all of them (default 0).
    int k = 0;
    /// Worker threads, 0 for OpenMP's default (default 0).
    int threads = 0;
};

struct NormalEstimate
{
    /// N  #P by 3 unit normals: the eigenvector of the smallest eigenvalue of the covariance of
    /// the point and its neighbours. Unoriented (the sign is arbitrary but deterministic).
    NormalMatrix normals;
    /// V  #P surface variation lambda0 / (lambda0 + lambda1 + lambda2) (Pauly et al.), 0 on a
    /// plane, up to 1/3 for isotropic scatter.
    Eigen::VectorXd variation;
    /// S  #P spread lambda1 / lambda2 of the neighbourhood in its own plane: near 0 where the
    /// neighbours lie along a line (one scan row), near 1 where they spread evenly.
    Eigen::VectorXd spread;
};

/// PCA normals of P over the neighbourhoods N.
NormalEstimate pcaNormals(const PointMatrix& P, const Neighbourhoods& N,
                          const NormalOptions& options = {});

/// The same normals for the listed rows of P only, written into `normals` (#P by 3); the other
/// rows are left as they are. For a sub-cloud whose neighbourhoods are those of its cloud
/// except where its border cuts them: the other rows keep the cloud's normals.
void pcaNormalsOfRows(const PointMatrix& P, const Neighbourhoods& N, const std::vector<int>& rows,
                      NormalMatrix& normals, const NormalOptions& options = {});

/// The mean and covariance of a cloud's rows.
struct Moments
{
    Eigen::RowVector3d mean;
    Eigen::Matrix3d covariance;
};

/// The mean and covariance of the rows of P taken `stride` apart (#P >= 1), taken about the
/// first row; the same at any number of threads.
Moments momentsOf(const PointMatrix& P, Eigen::Index stride = 1);

/// momentsOf(P, stride).covariance.
Eigen::Matrix3d covarianceOf(const PointMatrix& P, Eigen::Index stride = 1);

} // namespace featurelines
