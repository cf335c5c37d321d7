void tessref_raster_placeholder() {}
