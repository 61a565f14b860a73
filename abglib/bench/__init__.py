"""The benchmark matrix (extra ``abglib[bench]``): simulated radar datasets, named tracker
variants, Monte Carlo cell metrics, league tables and agreement with peer libraries.

``datasets``   seeded kinematics and noise, written as Parquet with a manifest
``variants``   the variant registry: a name and its parameters -> gains or a method
``metrics``    Monte Carlo metrics of one cell (variant x scenario)
``benchmark``  league tables over the matrix
``peers``      agreement with FilterPy, scipy.signal and python-control
``figures``    the benchmark report's figures (imports matplotlib)
"""
