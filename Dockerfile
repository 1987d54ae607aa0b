# Aerostat design tool: the Streamlit app on port 8501.
#   docker build -t aerostat-design .
#   docker run --rm -p 8501:8501 -v aerostat-data:/data aerostat-design
# Saved workspaces live in /data (a volume: they survive a new container). A team deployment
# with several replicas sets AEROSTAT_DATABASE_URL=postgresql+psycopg://user:password@host/db.
FROM python:3.11-slim

# One BLAS/OpenMP thread: small linear algebra ran up to 20x slower with threaded BLAS on 2 cores.
ENV OPENBLAS_NUM_THREADS=1 \
    OMP_NUM_THREADS=1 \
    PYTHONUNBUFFERED=1 \
    PYTHONDONTWRITEBYTECODE=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    STREAMLIT_BROWSER_GATHER_USAGE_STATS=false \
    NUMBA_CACHE_DIR=/var/cache/numba \
    AEROSTAT_DATA_DIR=/data

RUN groupadd --system --gid 10001 app \
    && useradd --system --uid 10001 --gid app --create-home --home-dir /home/app \
       --shell /usr/sbin/nologin app

WORKDIR /app

# Runtime dependencies only (exact pins); own layer so code changes do not reinstall them.
COPY requirements.txt .
RUN pip install --no-cache-dir -r requirements.txt

# The code stays owned by root: the app user can read it, not change it.
COPY . .

# Compile the dynamics' numba kernels once at build time (about 15 s), and the core's (the
# tether march and the envelope beam, by one default design: a few seconds), so the first
# simulation or design in a container does not pay for it; the cache stays writable for the
# app user.
RUN mkdir -p /var/cache/numba \
    && python -c "from aerostat_core.dynamics import warm_up; warm_up()" \
    && python -c "from aerostat_core import design; design()" \
    && chown -R 10001:10001 /var/cache/numba

# The workspace database (SQLite, WAL) in a volume owned by the app user.
RUN mkdir -p /data && chown 10001:10001 /data
VOLUME ["/data"]

# Numeric uid (the "app" user above): lets runtimes check runAsNonRoot without reading /etc/passwd.
USER 10001:10001

EXPOSE 8501

HEALTHCHECK --interval=30s --timeout=5s --start-period=30s --retries=3 \
    CMD ["python", "-c", "import sys, urllib.request; r = urllib.request.urlopen('http://localhost:8501/_stcore/health', timeout=4); sys.exit(0 if r.read().strip() == b'ok' else 1)"]

ENTRYPOINT ["python", "-m", "streamlit", "run", "app.py", "--server.address=0.0.0.0", "--server.port=8501", "--server.headless=true"]
